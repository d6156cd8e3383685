#pragma once
// A std::streambuf over a POSIX file descriptor, so that an AtomicFile can fsync what its
// stream wrote (std::ofstream hides its descriptor). Buffers 64 KiB; remembers the errno of
// the first write that failed, for the error message.

#include <streambuf>
#include <vector>

namespace legofeup::fileio {

class FdOutputBuffer : public std::streambuf {
  public:
    explicit FdOutputBuffer(int fd);

    /// The errno of the first failed write; 0 if every write so far succeeded.
    int error() const { return error_; }

  protected:
    int_type overflow(int_type ch) override;
    std::streamsize xsputn(const char* data, std::streamsize count) override;
    int sync() override;

  private:
    bool write_buffered();
    bool write_all(const char* data, std::size_t count);

    int fd_;
    int error_ = 0;
    std::vector<char> buffer_;
};

}  // namespace legofeup::fileio
