#include "fd_output_buffer.hpp"

#include <unistd.h>

#include <cerrno>

namespace legofeup::fileio {

namespace {
constexpr std::size_t kBufferSize = 64 * 1024;
}

FdOutputBuffer::FdOutputBuffer(int fd) : fd_(fd), buffer_(kBufferSize) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
}

FdOutputBuffer::int_type FdOutputBuffer::overflow(int_type ch) {
    if (!write_buffered()) {
        return traits_type::eof();
    }
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
        *pptr() = traits_type::to_char_type(ch);
        pbump(1);
    }
    return traits_type::not_eof(ch);
}

std::streamsize FdOutputBuffer::xsputn(const char* data, std::streamsize count) {
    const std::streamsize room = epptr() - pptr();
    if (count <= room) {
        traits_type::copy(pptr(), data, static_cast<std::size_t>(count));
        pbump(static_cast<int>(count));
        return count;
    }
    // Larger than the room left: what is buffered goes first, then these bytes directly.
    if (!write_buffered() || !write_all(data, static_cast<std::size_t>(count))) {
        return 0;
    }
    return count;
}

int FdOutputBuffer::sync() {
    return write_buffered() ? 0 : -1;
}

bool FdOutputBuffer::write_buffered() {
    const auto count = static_cast<std::size_t>(pptr() - pbase());
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return write_all(buffer_.data(), count);
}

bool FdOutputBuffer::write_all(const char* data, std::size_t count) {
    if (error_ != 0) {
        return false;  // after a failed write the file has a hole: write nothing more
    }
    while (count > 0) {
        const ssize_t written = ::write(fd_, data, count);
        if (written < 0) {
            if (errno == EINTR) {
                continue;
            }
            error_ = errno;
            return false;
        }
        if (written == 0) {
            error_ = EIO;  // no progress (a regular file never does this): stop, not spin
            return false;
        }
        data += written;
        count -= static_cast<std::size_t>(written);
    }
    return true;
}

}  // namespace legofeup::fileio
