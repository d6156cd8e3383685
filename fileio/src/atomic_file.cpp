#include "legofeup/fileio/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <utility>

#include "fd_output_buffer.hpp"

namespace legofeup::fileio {

namespace fs = std::filesystem;

namespace {

std::string error_text(const fs::path& path, const std::string& step, std::error_code reason) {
    return "cannot write " + path.string() + ": " + step + ": " + reason.message();
}

int open_retrying(const char* path, int flags, mode_t mode = 0) {
    int fd = -1;
    do {
        fd = ::open(path, flags, mode);
    } while (fd < 0 && errno == EINTR);
    return fd;
}

// Makes the rename durable: until the directory's entry is on disk, a power cut may bring
// back the old name's file (or none) although the new one's bytes were synced. Best effort
// on purpose: the rename has happened, every reader already sees the new file, so a failure
// here (EINVAL where a file system cannot sync directories) is not a failed write.
void sync_directory(const fs::path& file) {
    const fs::path parent = file.parent_path();
    const int fd =
        open_retrying(parent.empty() ? "." : parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

}  // namespace

WriteError::WriteError(fs::path path, std::string step, std::error_code reason)
    : std::runtime_error(error_text(path, step, reason)),
      path_(std::move(path)),
      step_(std::move(step)),
      reason_(reason) {}

class AtomicFile::Output {
  public:
    explicit Output(int descriptor) : fd(descriptor), buffer(descriptor), stream(&buffer) {}

    int fd;
    FdOutputBuffer buffer;
    std::ostream stream;
};

AtomicFile::AtomicFile(fs::path target)
    : target_(std::move(target)), temporary_(target_.string() + ".partial") {
    // O_NOFOLLOW: a symbolic link planted under the temporary name is refused, not written
    // through.
    const int fd = open_retrying(temporary_.c_str(),
                                 O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd < 0) {
        const int error = errno;
        throw WriteError(target_, "creating " + temporary_.string(),
                         std::error_code(error, std::system_category()));
    }
    output_ = std::make_unique<Output>(fd);
    // A file replaced keeps its permissions (a profile made private stays private).
    struct stat existing {};
    if (::stat(target_.c_str(), &existing) == 0 && S_ISREG(existing.st_mode)
        && ::fchmod(fd, existing.st_mode & 07777) != 0) {
        const int error = errno;
        fail("giving " + temporary_.string() + " the permissions of the file it replaces", error);
    }
}

AtomicFile::~AtomicFile() {
    if (done_) {
        return;
    }
    if (output_->fd >= 0) {
        ::close(output_->fd);
    }
    ::unlink(temporary_.c_str());
}

std::ostream& AtomicFile::stream() {
    return output_->stream;
}

bool AtomicFile::good() const {
    return output_->stream.good();
}

void AtomicFile::commit() {
    if (done_) {
        return;
    }
    output_->stream.flush();
    if (output_->buffer.error() != 0) {
        fail("writing " + temporary_.string(), output_->buffer.error());
    }
    if (!output_->stream) {
        fail("writing " + temporary_.string(), EIO);  // a writer set failbit itself
    }
    // The bytes reach the disk before the name points at them: otherwise a crash right after
    // the rename could leave the target empty (ext4, XFS delay the allocation).
    if (::fsync(output_->fd) != 0) {
        const int error = errno;
        fail("syncing " + temporary_.string() + " to disk", error);
    }
    const int fd = std::exchange(output_->fd, -1);
    if (::close(fd) != 0) {
        const int error = errno;
        fail("closing " + temporary_.string(), error);
    }
    if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
        const int error = errno;
        fail("renaming " + temporary_.string() + " over it", error);
    }
    done_ = true;
    sync_directory(target_);
}

void AtomicFile::fail(const std::string& step, int error) {
    if (output_ != nullptr && output_->fd >= 0) {
        ::close(std::exchange(output_->fd, -1));
    }
    ::unlink(temporary_.c_str());
    done_ = true;  // nothing left for the destructor to remove
    throw WriteError(target_, step, std::error_code(error, std::system_category()));
}

void write_file_atomically(const fs::path& target, std::string_view bytes) {
    AtomicFile file(target);
    file.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    file.commit();
}

}  // namespace legofeup::fileio
