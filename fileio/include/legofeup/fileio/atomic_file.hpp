#pragma once
// Writing a file so that it is either complete or not there, and a file it replaces stays
// intact until the new one is: the bytes go to `<target>.partial` in the target's directory
// (so that the rename below never crosses a file system), which is flushed and fsync'ed, then
// renamed over the target (rename(2) is atomic: a reader sees the old file or the new one,
// never half of either), and the directory is fsync'ed so that the rename itself survives a
// power cut. A failure at any step removes the temporary file and throws a WriteError naming
// the file, the step and the system's reason. The one writer of every output file: the CLI's
// outputs, the GUI's exports, robot profiles and reports. No Qt: the CLI links it.

#include <filesystem>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

namespace legofeup::fileio {

/// A write that failed: "cannot write PATH: STEP: REASON", e.g. "cannot write out/a.csv:
/// creating out/a.csv.partial: No such file or directory". The target is as it was.
class WriteError : public std::runtime_error {
  public:
    WriteError(std::filesystem::path path, std::string step, std::error_code reason);

    const std::filesystem::path& path() const { return path_; }  ///< the file meant
    const std::string& step() const { return step_; }            ///< what failed, naming its file
    std::error_code reason() const { return reason_; }           ///< errno's code

  private:
    std::filesystem::path path_;
    std::string step_;
    std::error_code reason_;
};

/// An output file being written. Write through stream(), then commit(); destroyed without a
/// commit (an exception on the way, say) it removes its temporary file and leaves the target
/// as it was.
class AtomicFile {
  public:
    /// Creates (or truncates) `<target>.partial`. Throws WriteError if it cannot.
    explicit AtomicFile(std::filesystem::path target);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// Buffered; a failed write sets the stream's badbit and commit() throws its reason.
    std::ostream& stream();
    bool good() const;
    const std::filesystem::path& path() const { return target_; }
    const std::filesystem::path& temporary_path() const { return temporary_; }

    /// Flushes, fsyncs and closes the temporary file, renames it over the target, fsyncs the
    /// directory. Throws WriteError (and removes the temporary file) if any of it fails
    /// before the rename; the target is then untouched. Once committed or failed, a further
    /// commit() does nothing.
    void commit();

  private:
    class Output;

    [[noreturn]] void fail(const std::string& step, int error);

    std::filesystem::path target_;
    std::filesystem::path temporary_;
    std::unique_ptr<Output> output_;
    bool done_ = false;  ///< committed, or failed and cleaned up
};

/// Writes `bytes` to `target` through an AtomicFile. Throws WriteError.
void write_file_atomically(const std::filesystem::path& target, std::string_view bytes);

}  // namespace legofeup::fileio
