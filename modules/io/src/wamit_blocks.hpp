#pragma once
// Private helper of the WAMIT readers: which entries each block of a table holds (the (i, j) pairs
// of one period in a .1 file, the modes of one period and heading in a .3 file), so that a file
// whose blocks differ is refused. WAMIT writes the same entries for every block; a file cut at a
// line end loses the tail of its last block, which would otherwise read as zeros.
#include <array>
#include <bitset>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::io::detail {

class WamitBlocks {
 public:
  static constexpr std::size_t kMaxEntries = 36;  // a 6×6 matrix's pairs; a .3 block uses 6
  using EntryName = std::function<std::string(std::size_t)>;  // "(1, 5)", "mode 3"

  WamitBlocks(std::filesystem::path path, EntryName entry_name) : path_(std::move(path)), entry_name_(std::move(entry_name)) {}

  // Entry `entry` of the block named `block` ("period 12.57 s") on line `line`; a second one of the
  // same block and entry is refused.
  void add(const std::string& block, std::size_t entry, int line) {
    auto [it, fresh] = index_.try_emplace(block, blocks_.size());
    if (fresh) blocks_.push_back({block, {}, {}, line});
    Block& b = blocks_[it->second];
    if (b.entries[entry])
      fail(line, fmt::format("{} of {} again (first on line {})", entry_name_(entry), block, b.first_line[entry]));
    b.entries.set(entry);
    b.first_line[entry] = line;
    b.last_line = line;
  }

  // Every block holds the entries of the first block, no more and no fewer.
  void check_complete() const {
    if (blocks_.empty()) return;
    const Block& first = blocks_.front();
    for (const Block& b : blocks_) {
      if (b.entries == first.entries) continue;
      std::vector<std::string> missing, extra;
      for (std::size_t e = 0; e < kMaxEntries; ++e) {
        if (first.entries[e] && !b.entries[e]) missing.push_back(entry_name_(e));
        if (!first.entries[e] && b.entries[e]) extra.push_back(entry_name_(e));
      }
      fail(b.last_line, fmt::format("{} holds {} entries where {} (ending on line {}) holds {}{}{}: every block of a "
                                    "complete file holds the same entries (cut short?)",
                                    b.name, b.entries.count(), first.name, first.last_line, first.entries.count(),
                                    missing.empty() ? "" : "; missing " + joined(missing),
                                    extra.empty() ? "" : "; extra " + joined(extra)));
    }
  }

 private:
  struct Block {
    std::string name;                              // "period 12.57 s"
    std::bitset<kMaxEntries> entries;              // entries present
    std::array<int, kMaxEntries> first_line{};     // line of each entry present
    int last_line = 0;                             // last line of the block
  };

  static std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
  }

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw InputError(ErrorContext{"io.wamit", std::nullopt, path_.filename().string(), ""},
                     fmt::format("{}:{}: {}", path_.string(), line, message));
  }

  std::filesystem::path path_;
  EntryName entry_name_;
  std::vector<Block> blocks_;
  std::map<std::string, std::size_t> index_;  // block name → position in blocks_
};

}  // namespace fowtsim::io::detail
