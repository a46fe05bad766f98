#!/usr/bin/python3
"""Deck fuzzer (issue 16, "Fuzzing in CI").

Mutates the shipped scene decks and the component decks they include (deleted keys, wrong types,
0 / negative / huge / NaN / inf numbers, truncation, garbage bytes, missing or bad includes, and
combinations), runs every mutant for 2 s of simulated time (a slender deck over its own span) and
requires of each run:

  * exit code 0, 2 or 3 (never a signal, never another code),
  * no hang (a per-case wall-clock limit, counted as a failure),
  * no NaN/Inf in any channel of an output whose HDF5 `status` is `completed` (nor in the `.out` or
    the slender profile table of a run that exited 0),
  * consistent files: exit 0 leaves an output whose HDF5 status is `completed`, exit 3 one marked
    `failed: ...`, and no `*.running.*` file is left behind (README "A failed start destroys nothing").

The YAML is mutated as text, line-wise (no PyYAML needed), so every case is also a parser test.
Cases are generated from a fixed seed: case N depends only on (seed, N) and the shipped decks, so a
failing case is reproduced with `--only N` (its mutant files are then kept and the command printed).

Mutants are written into a copy of inputs/ under WORKDIR, next to the file they replace
(`__fuzz_NNNN_<name>.yaml`), with the include lines of every file on the chain from the scene deck
to the mutated component rewritten to point at the mutants, so relative includes keep working.
Decks with turbulent wind (a field of a few seconds to generate) get a steady wind in most cases, a
short turbulence box in some and their own wind in a few.

usage: deck_fuzzer.py FOWTSIM INPUTS_DIR WORKDIR [--cases N] [--seed S] [--jobs J] [--timeout T]
                      [--only N[,M...]] [--keep]
Exit status: 0 when every case met the rules, 1 otherwise (every violating case listed).
"""
import argparse
import concurrent.futures
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
from collections import Counter, defaultdict
from pathlib import Path

import h5py
import numpy as np

# Scene decks (relative to inputs/) and their weight in the draw. Turbulent-wind decks are
# recognised from their text; the cheap ones are drawn more often.
SCENES = {
    "toy_coupled_oscillators.yaml": 3,
    "beams/rollup.yaml": 3,
    "oc3_hywind/free_decay_surge.yaml": 1,
    "oc3_hywind/free_decay_heave.yaml": 1,
    "oc3_hywind/free_decay_pitch.yaml": 1,
    "oc3_hywind/free_decay_yaw.yaml": 1,
    "oc3_hywind/turbine_steady_15mps.yaml": 3,
    "oc3_hywind/turbine_ntm_12mps_irregular.yaml": 2,
    "oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml": 3,
    "oc3_hywind/seed_validation_surge1000.yaml": 3,
    "oc3_hywind/platform_in_waves.yaml": 2,
    "oc3_hywind/sea_replay_example.yaml": 2,
    "seed_cases/table42_120m_typical.yaml": 1,
    "seed_cases/table42_120m_extreme.yaml": 1,
    "seed_cases/table42_120m_fixed.yaml": 1,
    "seed_cases/table42_74m_typical.yaml": 1,
    "seed_cases/table42_74m_extreme.yaml": 1,
    "seed_cases/table42_74m_fixed.yaml": 1,
    "slender/oc3_tower_harmonic.yaml": 1,
    "slender/oc3_tower_jonswap.yaml": 1,
    "slender/riser_harmonic.yaml": 1,
    "slender/riser_jonswap.yaml": 1,
}
T_RUN = 2.0  # simulated seconds per case (--tmax); every shipped deck's step divides it
# Scenes run over their deck's own span instead: the slender scene refuses a span without its
# start-up transient and a wave period after it, and solves a whole deck in about a second.
OWN_SPAN = ("slender/",)

KINDS = ["delete_key", "wrong_type", "number_zero", "number_negative", "number_huge", "number_nan",
         "number_inf", "truncate", "garbage", "missing_include", "multi"]
KIND_WEIGHTS = [12, 12, 8, 8, 8, 7, 7, 9, 10, 7, 12]

STEADY_WIND = "wind:\n  model: steady\n  speed_m_s: 12.0\n  reference_height_m: 90.0\n"
SHORT_TURBULENT_WIND = """wind:
  model: turbulent
  speed_m_s: 12.0
  reference_height_m: 90.0
  shear_exponent: 0.2
  turbulence:
    class: B
    model: NTM
    ny: 15
    nz: 15
    width_m: 145.0
    height_m: 145.0
    dt_s: 0.05
    duration_s: 40.0
    seed: 7
"""

KEY_RE = re.compile(r"^(?P<indent>\s*)(?P<dash>(?:-\s+)*)(?P<key>[A-Za-z_][\w.\-]*)\s*:(?=\s|$)(?P<rest>.*)$")
NUM_RE = re.compile(r"(?<![\w.+\-])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])")
FLOW_KEY_RE = re.compile(r"(?<=[{,])\s*(?P<key>[A-Za-z_]\w*)\s*:\s*(?P<val>\[[^\]]*\]|[^,{}\[\]]*)")
INCLUDE_ENTRY_RE = re.compile(r"[^\s,\[\]'\"#]+")

ZEROS = ["0", "0.0", "-0.0", "0e0"]
HUGE = ["1e300", "-1e300", "1.0e+308", "1e18", "9223372036854775807", "18446744073709551616",
        "4294967296", "2147483648", "1e999", "123456789012"]
NANS = [".nan", ".NaN", "nan", "NaN", "-.nan"]
INFS = [".inf", "-.inf", ".Inf", "inf", "-inf", "+.inf"]
WRONG_TYPES = ["abc", "true", "yes", "[1, 2, 3]", "{x: 1}", "[]", "{}", "~", "''", "\"1.0 m\"",
               "!!binary aGVsbG8=", "[[1, 2], [3]]", "[abc, def]", "2020-01-01", "0x1F", "1_000",
               "\"\"", "- 1", "|\n  text"]
GARBAGE_SNIPPETS = ["\t", "\x00", "\ufeff", ":", "- ", "[", "]", "{", "}", "&a ", "*a", "*undefined",
                    "!!binary ", "!<tag:x> ", "<<: *a", "%YAML 1.1\n", "---\n", "...\n", "? ", "|",
                    ">", "'", "\"", "\\", "#", "@", "`", ",", "\r", "\r\n", "\u00e9", "\u2028",
                    "key: value: other", "  bad indent: 1", "\n  - orphan", "{a: [1, {b: }",
                    "\x1b[31m", "%%%%"]


def split_comment(line):
    """(code, comment) of one YAML line: a '#' starts a comment at line start or after a blank."""
    for i, c in enumerate(line):
        if c == "#" and (i == 0 or line[i - 1] in " \t"):
            return line[:i], line[i:]
    return line, ""


def indent_of(line):
    return len(line) - len(line.lstrip(" "))


def is_blank(line):
    code, _ = split_comment(line)
    return not code.strip()


def key_lines(lines):
    """Every block-style `key:` line: (line index, key column, key, has inline value)."""
    out = []
    for i, line in enumerate(lines):
        code, _ = split_comment(line)
        m = KEY_RE.match(code)
        if m:
            col = len(m.group("indent")) + len(m.group("dash"))
            out.append((i, col, m.group("key"), bool(m.group("rest").strip())))
    return out


def block_end(lines, i, col, inline):
    """Index after the last line that belongs to the value of the key on line i."""
    j = i + 1
    while j < len(lines):
        line = lines[j]
        if is_blank(line):
            j += 1
            continue
        ind = indent_of(line)
        if ind > col or (not inline and ind == col and line.lstrip().startswith("- ")):
            j += 1
            continue
        break
    # leave trailing blank/comment lines where they were
    while j > i + 1 and is_blank(lines[j - 1]):
        j -= 1
    return j


def value_spans(lines):
    """(line, start, end) of the value text after 'key:' on key lines and of list-item lines."""
    spans = []
    for i, line in enumerate(lines):
        code, _ = split_comment(line)
        m = KEY_RE.match(code)
        if m:
            start = m.start("rest")
        elif code.lstrip().startswith("- ") or code.lstrip().startswith("[") or (
                code.strip() and indent_of(code) > 0 and i > 0):
            start = indent_of(code)
        else:
            continue
        if code[start:].strip():
            spans.append((i, start, len(code)))
    return spans


def number_tokens(lines, scalar_only):
    """(line, start, end, text) of numbers in values; scalar_only: numbers that are a key's whole value."""
    toks = []
    for i, line in enumerate(lines):
        code, _ = split_comment(line)
        m = KEY_RE.match(code)
        if scalar_only:
            if m:
                rest = m.group("rest")
                n = NUM_RE.fullmatch(rest.strip())
                if n:
                    s = m.start("rest") + rest.index(rest.strip())
                    toks.append((i, s, s + len(rest.strip()), rest.strip()))
            continue
        start = m.start("rest") if m else 0
        for n in NUM_RE.finditer(code, start):
            toks.append((i, n.start(), n.end(), n.group()))
    return toks


def include_refs(text):
    """Include paths named in a deck's text: (first line, last line, path) of each."""
    refs = []
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        code, _ = split_comment(lines[i])
        m = re.match(r"^\s*include\s*:(.*)$", code)
        if m:
            value = m.group(1)
            j = i
            if "[" in value:
                while "]" not in value and j + 1 < len(lines):
                    j += 1
                    value += " " + split_comment(lines[j])[0]
            for e in INCLUDE_ENTRY_RE.findall(value):
                refs.append((i, j, e))
            i = j + 1
            continue
        i += 1
    return refs


def remove_top_block(text, key):
    lines = text.split("\n")
    for i, col, k, inline in key_lines(lines):
        if col == 0 and k == key:
            end = block_end(lines, i, col, inline)
            del lines[i:end]
            return "\n".join(lines), True
    return text, False


class Case:
    def __init__(self, index):
        self.index = index
        self.kind = ""
        self.scene = ""
        self.target = ""
        self.wind = "own"
        self.desc = []
        self.files = {}      # relative path in the copied tree -> mutated text
        self.deck = ""       # relative path of the deck to run
        self.turbulent = False


class Fuzzer:
    def __init__(self, inputs, seed):
        self.inputs = Path(inputs)
        self.seed = seed
        self.texts = {}
        for p in self.inputs.rglob("*.yaml"):
            if "__fuzz_" not in p.name:
                self.texts[p.relative_to(self.inputs).as_posix()] = p.read_text(encoding="utf-8")
        self.other_files = sorted(p.relative_to(self.inputs).as_posix() for p in self.inputs.rglob("*")
                                  if p.is_file() and p.suffix != ".yaml")
        missing = [s for s in SCENES if s not in self.texts]
        if missing:
            raise SystemExit(f"deck_fuzzer: shipped decks not found under {self.inputs}: {missing}")

    # -- include graph ------------------------------------------------------------------------
    def resolve(self, rel_from, ref):
        return os.path.normpath(os.path.join(os.path.dirname(rel_from), ref)).replace(os.sep, "/")

    def chain_to_all(self, scene):
        """{file: [scene, ..., file]} for every file reached through includes from scene."""
        chains = {scene: [scene]}
        todo = [scene]
        while todo:
            f = todo.pop(0)
            for _, _, ref in include_refs(self.texts[f]):
                g = self.resolve(f, ref)
                if g in self.texts and g not in chains:
                    chains[g] = chains[f] + [g]
                    todo.append(g)
        return chains

    # -- mutations (each on a text, returns the new text and a description) ------------------
    def m_delete_key(self, rng, text, name):
        lines = text.split("\n")
        keys = key_lines(lines)
        flow = [(i, m) for i, line in enumerate(lines) for m in FLOW_KEY_RE.finditer(split_comment(line)[0])]
        if flow and (not keys or rng.random() < 0.15):
            i, m = rng.choice(flow)
            line = lines[i]
            lines[i] = line[:m.start()] + line[m.end():].lstrip(",").lstrip()
            if lines[i][m.start() - 1:m.start()] == "," and lines[i][m.start():m.start() + 1] == "}":
                lines[i] = lines[i][:m.start() - 1] + lines[i][m.start():]
            return "\n".join(lines), f"deleted flow key '{m.group('key')}' on line {i + 1}"
        if not keys:
            return self.m_truncate(rng, text, name)
        i, col, key, inline = rng.choice(keys)
        end = block_end(lines, i, col, inline)
        dash = re.match(r"^(\s*(?:-\s+)+)", lines[i])
        if dash and len(dash.group(1)) == col:
            # first key of a list item: keep the item, give the next sibling key the dash
            removed = lines[i:end]
            rest = lines[end:]
            if rest and indent_of(rest[0]) == col and KEY_RE.match(split_comment(rest[0])[0]):
                rest[0] = dash.group(1) + rest[0][col:]
                lines = lines[:i] + rest
            else:
                lines = lines[:i] + [dash.group(1).rstrip() + " {}"] + rest
            del removed
        else:
            del lines[i:end]
        return "\n".join(lines), f"deleted key '{key}' (line {i + 1}, {end - i} lines)"

    def m_wrong_type(self, rng, text, name):
        lines = text.split("\n")
        keys = [k for k in key_lines(lines) if k[2] != "include"] or key_lines(lines)
        if not keys:
            return self.m_garbage(rng, text, name)
        i, col, key, inline = rng.choice(keys)
        new = rng.choice(WRONG_TYPES)
        end = block_end(lines, i, col, inline)
        code, comment = split_comment(lines[i])
        head = code[:code.index(":", col) + 1]
        if "\n" in new:  # a block scalar: indent its body under the key
            first, body = new.split("\n", 1)
            repl = [head + " " + first] + [" " * (col + 2) + b.strip() for b in body.split("\n")]
        else:
            repl = [head + " " + new]
        lines[i:end] = repl
        return "\n".join(lines), f"key '{key}' (line {i + 1}) set to {new!r}"

    def _number(self, rng, text, choose, label):
        lines = text.split("\n")
        toks = number_tokens(lines, scalar_only=True) if rng.random() < 0.6 else []
        toks = toks or number_tokens(lines, scalar_only=False)
        if not toks:
            return self.m_wrong_type(rng, text, label)
        i, s, e, old = rng.choice(toks)
        new = choose(old)
        lines[i] = lines[i][:s] + new + lines[i][e:]
        return "\n".join(lines), f"number {old} on line {i + 1} -> {new}"

    def m_number_zero(self, rng, text, name):
        return self._number(rng, text, lambda old: rng.choice(ZEROS), name)

    def m_number_negative(self, rng, text, name):
        def neg(old):
            try:
                v = float(old)
            except ValueError:
                v = 1.0
            if v > 0:
                return "-" + old.lstrip("+")
            return rng.choice(["-1", "-1.0e6", "-0.001", "-123456789"])
        return self._number(rng, text, neg, name)

    def m_number_huge(self, rng, text, name):
        def huge(old):
            if rng.random() < 0.4:  # the same sign, scaled up: often still inside the key's range
                try:
                    v = float(old)
                except ValueError:
                    v = 1.0
                return repr(float((v if v != 0 else 1.0) * rng.choice([1e3, 1e6, 1e12])))
            return rng.choice(HUGE)
        return self._number(rng, text, huge, name)

    def m_number_nan(self, rng, text, name):
        return self._number(rng, text, lambda old: rng.choice(NANS), name)

    def m_number_inf(self, rng, text, name):
        return self._number(rng, text, lambda old: rng.choice(INFS), name)

    def m_truncate(self, rng, text, name):
        if not text:
            return text, "truncated (empty already)"
        mode = rng.random()
        if mode < 0.1:
            return "", "truncated to 0 bytes"
        if mode < 0.45:
            lines = text.split("\n")
            n = rng.randrange(len(lines))
            return "\n".join(lines[:n]) + "\n", f"truncated after line {n} of {len(lines)}"
        n = rng.randrange(1, len(text))
        return text[:n], f"truncated at character {n} of {len(text)} (mid-line)"

    def m_garbage(self, rng, text, name):
        mode = rng.random()
        pos = rng.randrange(len(text) + 1)
        if mode < 0.35:  # raw random bytes, carried as surrogate escapes when not UTF-8
            n = rng.randint(1, 24)
            raw = bytes(rng.randrange(256) for _ in range(n))
            junk = raw.decode("utf-8", "surrogateescape")
            return text[:pos] + junk + text[pos:], f"{n} random bytes {raw.hex()} at char {pos}"
        if mode < 0.7:
            snip = "".join(rng.choice(GARBAGE_SNIPPETS) for _ in range(rng.randint(1, 3)))
            return text[:pos] + snip + text[pos:], f"inserted {snip!r} at char {pos}"
        lines = text.split("\n")
        i = rng.randrange(len(lines))
        n = rng.randint(1, 60)
        junk = "".join(chr(rng.randrange(32, 127)) for _ in range(n))
        old = lines[i]
        if rng.random() < 0.5:
            lines[i] = " " * indent_of(old) + junk
            what = "replaced by"
        else:  # overwrite a span inside the line
            s = rng.randrange(len(old) + 1)
            lines[i] = old[:s] + junk + old[s + len(junk):]
            what = "overwritten with"
        return "\n".join(lines), f"line {i + 1} {what} {junk!r}"

    def m_missing_include(self, rng, text, name, own_name=None):
        refs = include_refs(text)
        here = os.path.dirname(name)
        choices = ["missing", "missing", "missing_abs", "directory", "empty", "non_yaml", "self"]
        how = rng.choice(choices)
        if how == "missing":
            new = rng.choice(["no_such_file.yaml", "../no_such_dir/x.yaml", "hydro.yml", "sub/"
                              "deeper/missing.yaml"])
        elif how == "missing_abs":
            new = "/nonexistent/fowtsim/fuzz.yaml"
        elif how == "directory":
            new = rng.choice([".", "..", "../oc3_hywind"])
        elif how == "empty":
            new = "''"
        elif how == "non_yaml":
            other = rng.choice(self.other_files) if self.other_files else "README.md"
            new = os.path.relpath(other, here or ".").replace(os.sep, "/")
        else:
            new = os.path.basename(own_name or name)
        lines = text.split("\n")
        if refs and rng.random() < 0.85:
            i, last, ref = rng.choice(refs)
            # replace that entry (on the include line or its continuation lines)
            for j in range(i, last + 1):
                if ref in lines[j]:
                    lines[j] = lines[j].replace(ref, new, 1)
                    break
            return "\n".join(lines), f"include '{ref}' -> '{new}' ({how})"
        # no include here (or chosen so): add one at the top level
        lines.insert(0, f"include: {new}")
        return "\n".join(lines), f"added 'include: {new}' ({how})"

    def m_multi(self, rng, text, name, own_name=None):
        n = rng.randint(2, 4)
        descs = []
        for _ in range(n):
            k = rng.choice([k for k in KINDS if k not in ("multi", "truncate")])
            text, d = self.apply(k, rng, text, name, own_name)
            descs.append(f"{k}: {d}")
        return text, " + ".join(descs)

    def apply(self, kind, rng, text, name, own_name=None):
        if kind in ("missing_include", "multi"):
            return getattr(self, "m_" + kind)(rng, text, name, own_name)
        return getattr(self, "m_" + kind)(rng, text, name)

    # -- one case -------------------------------------------------------------------------------
    def make_case(self, index):
        rng = random.Random(f"deck-fuzzer:{self.seed}:{index}")
        c = Case(index)
        scenes = list(SCENES)
        c.scene = rng.choices(scenes, weights=[SCENES[s] for s in scenes])[0]
        c.kind = rng.choices(KINDS, weights=KIND_WEIGHTS)[0]
        chains = self.chain_to_all(c.scene)
        texts = {f: self.texts[f] for f in chains}
        c.turbulent = any(re.search(r"model:\s*turbulent", t) for t in texts.values())

        # wind: steady in most turbulent cases (the field takes seconds to generate)
        if c.turbulent:
            r = rng.random()
            c.wind = "steady" if r < 0.8 else ("short_turbulence" if r < 0.95 else "own")
            if c.wind != "own":
                t, _ = remove_top_block(texts[c.scene], "wind")
                texts[c.scene] = t.rstrip("\n") + "\n" + (STEADY_WIND if c.wind == "steady"
                                                          else SHORT_TURBULENT_WIND)

        # target: the scene deck itself, or one of the files it includes (at any depth)
        if c.kind == "missing_include":
            with_inc = [f for f in chains if include_refs(texts[f])] or [c.scene]
            c.target = rng.choice(with_inc)
        else:
            c.target = c.scene if rng.random() < 0.5 or len(chains) == 1 else rng.choice(sorted(chains))
        chain = chains[c.target]

        def mutant_name(f):
            d, b = os.path.split(f)
            return (d + "/" if d else "") + f"__fuzz_{index:04d}_{b}"

        texts[c.target], d = self.apply(c.kind, rng, texts[c.target], c.target, mutant_name(c.target))
        c.desc.append(d)

        # write every file on the chain under its mutant name, include lines redirected
        changed = set(chain) | ({c.scene} if c.wind != "own" else set())
        for parent, child in zip(chain, chain[1:]):
            new_texts = []
            lines = texts[parent].split("\n")
            for first, last, ref in include_refs(texts[parent]):
                if self.resolve(parent, ref) == child:
                    d_ref, b_ref = os.path.split(ref)
                    new_ref = (d_ref + "/" if d_ref else "") + f"__fuzz_{index:04d}_{b_ref}"
                    pattern = r"(?<![\w./])" + re.escape(ref) + r"(?![\w./])"
                    for j in range(first, last + 1):
                        code, comment = split_comment(lines[j])
                        lines[j] = re.sub(pattern, new_ref, code) + comment
                    new_texts.append(new_ref)
            texts[parent] = "\n".join(lines)
            if not new_texts:  # the chain link was lost (should not happen on the shipped decks)
                c.desc.append(f"(could not redirect include of {child} in {parent})")
        for f in changed:
            c.files[mutant_name(f)] = texts[f]
        c.deck = mutant_name(c.scene)
        return c


# ---------------------------------------------------------------------------------------------
def check_outputs(out_base, rc):
    """Problems found in the files a run left (list of strings) and the HDF5 status seen."""
    problems = []
    status = None
    d = out_base.parent
    stem = out_base.name
    files = sorted(p for p in d.iterdir() if p.name == stem + ".h5" or p.name == stem + ".out"
                   or p.name.startswith(stem + "."))
    running = [p.name for p in files if ".running." in p.name]
    if running:
        problems.append(f"left behind {running} after exit {rc}")
    h5 = out_base.with_name(stem + ".h5")
    out = out_base.with_name(stem + ".out")
    if h5.exists():
        try:
            with h5py.File(h5, "r") as f:
                status = f.attrs.get("status")
                if isinstance(status, bytes):
                    status = status.decode("utf-8", "replace")
                if status == "completed":
                    bad = []
                    for name, ds in f.items():
                        if isinstance(ds, h5py.Dataset) and ds.dtype.kind in "fc":
                            v = ds[()]
                            if not np.all(np.isfinite(v)):
                                bad.append(f"{name} ({int(np.size(v) - np.count_nonzero(np.isfinite(v)))} non-finite)")
                    if bad:
                        problems.append("NaN/Inf in completed file: " + ", ".join(bad[:8])
                                        + (f" … ({len(bad)} channels)" if len(bad) > 8 else ""))
        except OSError as e:
            problems.append(f"cannot read {h5.name}: {e}")
        if rc == 0 and status != "completed":
            problems.append(f"exit 0 but HDF5 status {status!r}")
        if rc == 3 and status is not None and not str(status).startswith("failed"):
            problems.append(f"exit 3 but HDF5 status {status!r}")
    if rc == 0 and out.exists():
        lines = out.read_text(encoding="utf-8", errors="replace").splitlines()
        head = next((i for i, l in enumerate(lines) if l.split() and l.split()[0] == "Time"), None)
        if head is None:
            problems.append(f"no 'Time' header in {out.name} of a run that exited 0")
        else:
            bad = [n + head + 3 for n, l in enumerate(lines[head + 2:])
                   if re.search(r"(?i)(?<![a-z])(nan|inf)", l)]
            if bad:
                problems.append(f"NaN/Inf in {out.name} of a run that exited 0 (lines {bad[:5]})")
    # The slender scene's profile table (a frequency-domain run writes nothing else).
    tables = [p for p in (out_base.with_name(stem + ".amplitude.csv"), out_base.with_name(stem + ".rms.csv"))
              if p.exists()]
    for table in tables:
        if rc == 0 and re.search(r"(?i)(?<![a-z])(nan|inf)", table.read_text(encoding="utf-8", errors="replace")):
            problems.append(f"NaN/Inf in {table.name} of a run that exited 0")
    if rc == 0 and not h5.exists() and not out.exists() and not tables:
        problems.append("exit 0 but no output file")
    return problems, status


def run_case(fowtsim, work, case, timeout, mem_mb, keep):
    tree = work / "inputs"
    for rel, text in case.files.items():
        (tree / rel).write_text(text, encoding="utf-8", errors="surrogateescape")
    out_base = work / "out" / f"case_{case.index:04d}" / "run"
    out_base.parent.mkdir(parents=True, exist_ok=True)
    deck = tree / case.deck
    cmd = [fowtsim, "run", str(deck), "-o", str(out_base)]
    if not case.scene.startswith(OWN_SPAN):
        cmd += ["--tmax", f"{T_RUN:g}"]
    # a memory limit so that a mutant asking for absurd sizes fails inside fowtsim (bad_alloc)
    # instead of taking the machine down; `exec` keeps fowtsim as the child (signals seen as such)
    wrapped = ["/bin/sh", "-c", f'ulimit -v {mem_mb * 1024} 2>/dev/null; exec "$@"', "sh"] + cmd
    t0 = time.monotonic()
    rc, hang, stderr, stdout = None, False, "", ""
    # own process group, so that a hung run is killed with anything it started
    p = subprocess.Popen(wrapped, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, cwd=work, start_new_session=True)
    try:
        out, err = p.communicate(timeout=timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        hang = True
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, err = p.communicate()
    stderr, stdout = err.decode("utf-8", "replace"), out.decode("utf-8", "replace")
    wall = time.monotonic() - t0
    problems = []
    status = None
    if hang:
        problems.append(f"hang: no exit within {timeout:g} s")
    elif rc < 0:
        problems.append(f"crash: killed by signal {-rc}")
    elif rc not in (0, 2, 3):
        problems.append(f"exit code {rc} (allowed: 0, 2, 3)")
    if not hang:
        more, status = check_outputs(out_base, rc)
        problems += more
    result = dict(index=case.index, kind=case.kind, scene=case.scene, target=case.target,
                  wind=case.wind, turbulent=case.turbulent,
                  files=[str(tree / rel) for rel in sorted(case.files)], desc=" | ".join(case.desc), rc=rc, hang=hang, wall=wall,
                  status=status, problems=problems, cmd=cmd,
                  stderr_tail="\n".join(stderr.strip().splitlines()[-12:]),
                  stdout_tail="\n".join(stdout.strip().splitlines()[-6:]))
    if not problems and not keep:
        for rel in case.files:
            try:
                (tree / rel).unlink()
            except FileNotFoundError:
                pass
        shutil.rmtree(out_base.parent, ignore_errors=True)
    return result


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("fowtsim")
    ap.add_argument("inputs", help="the repository's inputs/ folder")
    ap.add_argument("workdir", help="scratch folder (emptied first; removed when every case passes)")
    ap.add_argument("--cases", type=int, default=300)
    ap.add_argument("--seed", type=int, default=16)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=60.0, help="wall-clock limit per case, s")
    ap.add_argument("--mem-mb", type=int, default=2048, help="address-space limit per run, MiB")
    ap.add_argument("--only", default="", help="comma-separated case numbers (keeps their files)")
    ap.add_argument("--keep", action="store_true", help="keep every mutant and output")
    ap.add_argument("--verbose", action="store_true", help="one line per case")
    args = ap.parse_args()

    t_start = time.monotonic()
    fowtsim = os.path.abspath(args.fowtsim)
    if not os.access(fowtsim, os.X_OK):
        print(f"deck_fuzzer: {fowtsim} is not an executable", file=sys.stderr)
        return 2
    fuzzer = Fuzzer(args.inputs, args.seed)
    work = Path(args.workdir).resolve()
    shutil.rmtree(work, ignore_errors=True)
    (work / "out").mkdir(parents=True)
    shutil.copytree(fuzzer.inputs, work / "inputs",
                    ignore=shutil.ignore_patterns("__fuzz_*"))

    indices = [int(x) for x in args.only.split(",") if x.strip()] if args.only else range(args.cases)
    keep = args.keep or bool(args.only)
    cases = [fuzzer.make_case(i) for i in indices]

    results = []
    lock = threading.Lock()
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = [pool.submit(run_case, fowtsim, work, c, args.timeout, args.mem_mb, keep) for c in cases]
        for fut in concurrent.futures.as_completed(futures):
            r = fut.result()
            with lock:
                results.append(r)
    results.sort(key=lambda r: r["index"])
    elapsed = time.monotonic() - t_start

    # ---- report ----------------------------------------------------------------------------
    def code_label(r):
        if r["hang"]:
            return "hang"
        return f"signal {-r['rc']}" if r["rc"] < 0 else f"exit {r['rc']}"

    def code_order(label):
        parts = label.split()
        number = int(parts[1]) if len(parts) > 1 and parts[1].isdigit() else 0
        return (not label.startswith("exit"), number, label)

    codes = sorted({code_label(r) for r in results}, key=code_order)
    per_kind = defaultdict(Counter)
    for r in results:
        per_kind[r["kind"]][code_label(r)] += 1
    if args.verbose:
        for r in results:
            msg = [l.strip() for l in r["stderr_tail"].splitlines() if l.strip()]
            first = next((l for l in msg if not l.endswith(":")), msg[0] if msg else "")
            print(f"#{r['index']:04d} {code_label(r):>7} {r['wall']:5.2f} s {r['kind']:<15} {r['scene']}"
                  f" [{r['target']}] {r['desc'][:200]!r} :: {first[:200]}")
    width = max(len(k) for k in KINDS + ["mutation"])
    print(f"deck fuzzer: seed {args.seed}, {len(results)} cases, {args.jobs} jobs, "
          f"--tmax {T_RUN:g}, timeout {args.timeout:g} s per case")
    print(f"{'mutation':<{width}}  {'cases':>5}  " + "  ".join(f"{c:>8}" for c in codes))
    for k in KINDS:
        if per_kind[k]:
            row = per_kind[k]
            print(f"{k:<{width}}  {sum(row.values()):>5}  " + "  ".join(f"{row[c]:>8}" for c in codes))
    scene_counts = Counter(r["scene"] for r in results)
    print("decks: " + ", ".join(f"{s} {n}" for s, n in sorted(scene_counts.items())))
    winds = Counter(r["wind"] for r in results if r["turbulent"])
    if winds:
        print("turbulent-wind decks: " + ", ".join(f"{w} {n}" for w, n in sorted(winds.items())))
    slow = sorted(results, key=lambda r: -r["wall"])[:3]
    print("slowest cases: " + ", ".join(f"#{r['index']} {r['wall']:.1f} s" for r in slow))

    total = Counter(code_label(r) for r in results)
    crashes = [r for r in results if not r["hang"] and r["rc"] < 0]
    hangs = [r for r in results if r["hang"]]
    other = [r for r in results if not r["hang"] and r["rc"] >= 0 and r["rc"] not in (0, 2, 3)]
    nan = [r for r in results if any("NaN/Inf" in p for p in r["problems"])]
    violations = [r for r in results if r["problems"]]
    inconsistent = [r for r in violations if r not in crashes + hangs + other + nan]
    exit_part = ", ".join(f"{total[c]} {c}" for c in codes if c.startswith("exit")) or "no exit"
    print(f"{len(results)} cases: {exit_part}; {len(crashes)} crashes, {len(hangs)} hangs, "
          f"{len(other)} other exit codes, {len(nan)} NaN in completed files, "
          f"{len(inconsistent)} inconsistent files; {elapsed:.1f} s")

    if violations:
        rerun = (f"/usr/bin/python3 {os.path.abspath(__file__)} {fowtsim} {fuzzer.inputs.resolve()} "
                 f"{work} --seed {args.seed} --only N")
        print(f"\n{len(violations)} VIOLATIONS (mutants kept under {work / 'inputs'}; regenerate and rerun "
              f"case N alone with: {rerun})")
        for r in violations:
            print(f"\n--- case {r['index']}: {'; '.join(r['problems'])}")
            print(f"  mutation : {r['kind']}: {r['desc']}")
            print(f"  deck     : {r['scene']} (mutated file {r['target']}, wind {r['wind']})")
            print(f"  result   : {code_label(r)}, HDF5 status {r['status']!r}, {r['wall']:.1f} s")
            print(f"  mutants  : {', '.join(r['files'])}")
            print(f"  reproduce: {' '.join(r['cmd'])}")
            for what in ("stderr", "stdout"):
                if r[what + "_tail"]:
                    print(f"  {what} tail:\n" + "\n".join("    " + l for l in r[what + "_tail"].splitlines()))
        return 1
    if not keep:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
