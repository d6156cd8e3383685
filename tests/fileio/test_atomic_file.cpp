// The atomic file writer: the target is the old file or the whole new one, never half; a
// failure at any step leaves the old file, no temporary file, and an error naming the file,
// the step and errno's text. The failures are provoked in ways that work as root too (root
// ignores permissions): a parent that is a regular file, a file-size limit (RLIMIT_FSIZE), a
// target that is a directory. The permission case says which kind of user ran it.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "legofeup/fileio/atomic_file.hpp"

namespace legofeup::fileio {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void put(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

/// Every name in `directory`, sorted, as one string ("a b c").
std::string names_in(const fs::path& directory) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    std::string out;
    for (const std::string& name : names) {
        out += (out.empty() ? "" : " ") + name;
    }
    return out;
}

/// `count` bytes that differ from position to position, so a lost or repeated block shows.
std::string pattern(std::size_t count) {
    std::string text(count, '\0');
    for (std::size_t i = 0; i < count; ++i) {
        text[i] = static_cast<char>('a' + (i * 7 + i / 251) % 26);
    }
    return text;
}

class AtomicFileTest : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / "legofeup_fileio_tests" / info->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ignored);
        fs::remove_all(dir_, ignored);
    }

    fs::path dir_;
};

TEST_F(AtomicFileTest, TheTargetIsTheOldFileUntilCommitThenTheWholeNewOne) {
    const fs::path target = dir_ / "trace.csv";
    put(target, "old\n");
    {
        AtomicFile file(target);
        file.stream() << "new line 1\n";
        file.stream().flush();             // even written through to the temporary file…
        EXPECT_EQ(read(target), "old\n");  // …the target is untouched
        EXPECT_EQ(read(file.temporary_path()), "new line 1\n");
        EXPECT_EQ(file.temporary_path(), dir_ / "trace.csv.partial");  // in the same directory
        file.stream() << "new line 2\n";
        EXPECT_TRUE(file.good());
        file.commit();
        EXPECT_EQ(read(target), "new line 1\nnew line 2\n");
    }
    EXPECT_EQ(names_in(dir_), "trace.csv");  // no temporary file left
}

TEST_F(AtomicFileTest, AnAbandonedWriteLeavesTheOldFileAndNoTemporaryFile) {
    const fs::path target = dir_ / "summary.json";
    put(target, "{}\n");
    {
        AtomicFile file(target);
        file.stream() << pattern(100'000);  // more than the buffer: part of it is on disk
        EXPECT_TRUE(fs::exists(file.temporary_path()));
    }
    EXPECT_EQ(read(target), "{}\n");
    EXPECT_EQ(names_in(dir_), "summary.json");
}

TEST_F(AtomicFileTest, WritesEveryByteOfSmallAndLargePiecesInOrder) {
    // Pieces smaller than the 64 KiB buffer, one larger (written past it), across its edges.
    const std::string small = pattern(1000);
    const std::string large = pattern(200'000);
    std::string expected;
    AtomicFile file(dir_ / "out.bin");
    for (int i = 0; i < 70; ++i) {
        file.stream() << small;
        expected += small;
        file.stream().put(static_cast<char>('0' + i % 10));
        expected += static_cast<char>('0' + i % 10);
    }
    file.stream() << large;
    expected += large;
    file.stream() << small;
    expected += small;
    file.commit();
    EXPECT_EQ(read(dir_ / "out.bin"), expected);
}

TEST_F(AtomicFileTest, WriteFileAtomicallyCreatesAndReplaces) {
    const fs::path target = dir_ / "profile.toml";
    write_file_atomically(target, "");
    EXPECT_TRUE(fs::is_regular_file(target));
    EXPECT_EQ(fs::file_size(target), 0U);
    write_file_atomically(target, "codo_right = 1\n");
    EXPECT_EQ(read(target), "codo_right = 1\n");
    EXPECT_EQ(names_in(dir_), "profile.toml");
}

TEST_F(AtomicFileTest, AReplacedFileKeepsItsPermissions) {
    const fs::path target = dir_ / "private.toml";
    put(target, "old");
    fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write);
    write_file_atomically(target, "new");
    EXPECT_EQ(read(target), "new");
    EXPECT_EQ(fs::status(target).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write);
}

TEST_F(AtomicFileTest, AParentThatIsAFileFailsAtCreationNamingFileStepAndReason) {
    put(dir_ / "file", "x");
    const fs::path target = dir_ / "file" / "report.html";
    try {
        AtomicFile file(target);
        FAIL() << "no error";
    } catch (const WriteError& error) {
        EXPECT_EQ(error.path(), target);
        EXPECT_EQ(error.step(), "creating " + target.string() + ".partial");
        EXPECT_EQ(error.reason().value(), ENOTDIR);
        EXPECT_EQ(std::string(error.what()), "cannot write " + target.string() + ": creating "
                                                 + target.string()
                                                 + ".partial: " + std::strerror(ENOTDIR));
    }
    EXPECT_EQ(read(dir_ / "file"), "x");
    EXPECT_EQ(names_in(dir_), "file");
}

// Writes past a file-size limit fail with EFBIG (and SIGXFSZ, ignored here) for any user.
class FileSizeLimit {
  public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &saved_);
        rlimit limited = saved_;
        limited.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &limited);
        saved_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &saved_);
        std::signal(SIGXFSZ, saved_handler_);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

  private:
    rlimit saved_{};
    void (*saved_handler_)(int) = nullptr;
};

TEST_F(AtomicFileTest, AFailedWriteKeepsTheOldFileAndSaysWhy) {
    const fs::path target = dir_ / "trace.csv";
    put(target, "the old trace\n");
    AtomicFile file(target);
    try {
        const FileSizeLimit limit(10'000);
        file.stream() << pattern(300'000);
        EXPECT_FALSE(file.good());  // the stream says so at once…
        file.commit();              // …and commit() says why
        FAIL() << "no error";
    } catch (const WriteError& error) {
        EXPECT_EQ(error.reason().value(), EFBIG);
        EXPECT_EQ(error.step(), "writing " + target.string() + ".partial");
        EXPECT_NE(std::string(error.what()).find(std::strerror(EFBIG)), std::string::npos)
            << error.what();
    }
    EXPECT_EQ(read(target), "the old trace\n");
    EXPECT_EQ(names_in(dir_), "trace.csv");
}

TEST_F(AtomicFileTest, AFailedRenameKeepsTheTargetAndRemovesTheTemporaryFile) {
    // The target's name is taken by a directory that is not empty: rename(2) refuses.
    const fs::path target = dir_ / "results.csv";
    fs::create_directories(target / "inside");
    AtomicFile file(target);
    file.stream() << "a,b\n";
    try {
        file.commit();
        FAIL() << "no error";
    } catch (const WriteError& error) {
        EXPECT_EQ(error.step(), "renaming " + target.string() + ".partial over it");
        EXPECT_EQ(error.reason().value(), EISDIR);
    }
    EXPECT_TRUE(fs::is_directory(target / "inside"));
    EXPECT_EQ(names_in(dir_), "results.csv");
}

TEST_F(AtomicFileTest, ADirectoryWithoutWritePermissionRefusesUnlessTheUserBypassesIt) {
    const fs::path target = dir_ / "locked" / "grade.json";
    fs::create_directories(target.parent_path());
    put(target, "old");
    fs::permissions(target.parent_path(), fs::perms::owner_read | fs::perms::owner_exec);
    // Root (or CAP_DAC_OVERRIDE) writes anyway: find out which case this is.
    const fs::path probe = target.parent_path() / "probe";
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT, 0600);
    const bool permissions_enforced = fd < 0;
    if (fd >= 0) {
        ::close(fd);
        ::unlink(probe.c_str());
    }
    if (permissions_enforced) {
        try {
            write_file_atomically(target, "new");
            FAIL() << "no error";
        } catch (const WriteError& error) {
            EXPECT_EQ(error.reason().value(), EACCES);
            EXPECT_EQ(error.step(), "creating " + target.string() + ".partial");
        }
        EXPECT_EQ(read(target), "old");
    } else {
        SCOPED_TRACE("permissions are not enforced for this user (root): the write succeeds");
        write_file_atomically(target, "new");
        EXPECT_EQ(read(target), "new");
    }
    fs::permissions(target.parent_path(), fs::perms::owner_all);
    EXPECT_EQ(names_in(target.parent_path()), "grade.json");
}

}  // namespace
}  // namespace legofeup::fileio
