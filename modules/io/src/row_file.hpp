#pragma once
// Private to the io writers: the file of a writer whose output grows by whole rows after a header
// with a fixed-width status field (the text .out and the binary .outb), so that creating it,
// writing it, marking it unfinished and closing it, with their error messages, are written once.
#include <sys/types.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace fowtsim::io::detail {

class RowFile {
 public:
  // `component` names the writer in errors ("io.text", "io.outb"); nothing is opened before create().
  RowFile(const char* component, std::string path_text);
  ~RowFile();  // closes a file still open (after mark_unfinished)
  RowFile(const RowFile&) = delete;
  RowFile& operator=(const RowFile&) = delete;

  [[noreturn]] void fail(const std::string& message, const std::string& hint = "") const;

  void create();  // truncates a file already there

  // Writes [data, data + size) at `offset`. A failed write at or past the end of the whole rows is
  // cut back to that end, so the file never ends in a partial row; `what` names it in the error.
  void write_at(const void* data, std::size_t size, off_t offset, std::string_view what);
  // The same after the last whole row; once written, the bytes count as whole rows.
  void append(const void* data, std::size_t size, std::string_view what);

  void set_status_offset(off_t offset) { status_offset_ = offset; }  // where the status text starts
  void write_status(const std::string& status);

  // For a writer's destructor, reached without finish(): keeps every row that `write_pending` can
  // still write and says so in the status; nothing may throw. Nothing to do if no file is open.
  template <class WritePending>
  void mark_unfinished(WritePending&& write_pending) noexcept {
    if (fd_ < 0) return;
    try {
      write_pending();
    } catch (...) {
    }
    try {
      write_status("incomplete: output closed before the run finished");
    } catch (...) {
    }
  }

  void close();  // the file is closed even when this throws

 private:
  const char* component_;
  std::string path_text_;
  int fd_ = -1;
  off_t durable_bytes_ = 0;  // bytes of the header and whole rows in the file
  off_t status_offset_ = 0;
};

}  // namespace fowtsim::io::detail
