"""Factors between the units OpenFAST and fowtsim write, for overlaying one run on another: the
same table as `fowtsim compare` (driver/verification/compare/channel_units.cpp), kept short."""
import math


class UnitError(Exception):
    pass


# unit → (dimension, factor to the dimension's SI unit); spellings as the files write them.
_UNITS = {
    "N": ("force", 1.0), "kN": ("force", 1e3), "MN": ("force", 1e6),
    "N-m": ("moment", 1.0), "N·m": ("moment", 1.0), "Nm": ("moment", 1.0),
    "kN-m": ("moment", 1e3), "kN·m": ("moment", 1e3), "kNm": ("moment", 1e3),
    "MN-m": ("moment", 1e6), "MN·m": ("moment", 1e6), "MNm": ("moment", 1e6),
    "rad": ("angle", 1.0), "deg": ("angle", math.pi / 180.0),
    "rad/s": ("angular speed", 1.0), "deg/s": ("angular speed", math.pi / 180.0), "rpm": ("angular speed", math.pi / 30.0),
    "m": ("length", 1.0), "mm": ("length", 1e-3),
    "W": ("power", 1.0), "kW": ("power", 1e3), "MW": ("power", 1e6),
}


def factor_between(unit, target):
    """The factor that turns values in `unit` into `target`: 1 for the same spelling, else from the
    table; UnitError when either is unknown or they measure different things."""
    if unit == target:
        return 1.0
    if unit not in _UNITS or target not in _UNITS:
        unknown = unit if unit not in _UNITS else target
        raise UnitError(f"units ({unit}) and ({target}) differ and ({unknown}) has no known conversion")
    (dim, to_si), (target_dim, target_to_si) = _UNITS[unit], _UNITS[target]
    if dim != target_dim:
        raise UnitError(f"units ({unit}) and ({target}) are not comparable: {dim} against {target_dim}")
    return to_si / target_to_si
