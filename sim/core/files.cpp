#include "sim/core/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "sim/core/errors.hpp"

namespace mmv {

bool readInputFile(const std::string& path, long max_bytes, std::string& contents, std::string& why,
                   InputFileProblem* problem) {
  InputFileProblem unused;
  InputFileProblem& p = problem ? *problem : unused;
  const auto fail = [&](InputFileProblem kind, std::string text) {
    p = kind, why = std::move(text);
    return false;
  };
  struct stat st {};
  if (path.empty()) return fail(InputFileProblem::CannotOpen, "empty path");
  if (::stat(path.c_str(), &st) != 0) return fail(InputFileProblem::CannotOpen, std::strerror(errno));
  if (S_ISDIR(st.st_mode)) return fail(InputFileProblem::NotRegular, "is a directory");
  if (!S_ISREG(st.st_mode)) return fail(InputFileProblem::NotRegular, "is not a regular file (a device, FIFO or socket)");
  if (st.st_size > max_bytes)
    return fail(InputFileProblem::TooLarge,
                std::to_string(st.st_size) + " bytes, above the limit of " + std::to_string(max_bytes) + " bytes");
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(InputFileProblem::CannotOpen, std::strerror(errno));
  std::ostringstream os;
  os << in.rdbuf();
  if (in.bad()) return fail(InputFileProblem::CannotOpen, "cannot be read");
  p = InputFileProblem::None;
  contents = os.str();
  return true;
}

namespace {

[[noreturn]] void cannotWrite(const std::string& path, int err) {
  throw OutputError(path + ": cannot write: " + std::strerror(err));
}

}  // namespace

void writeFileChecked(const std::string& path, std::string_view bytes) {
  writeFileChecked(path, std::vector<std::string_view>{bytes});
}

void writeFileChecked(const std::string& path, const std::vector<std::string_view>& pieces) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) cannotWrite(path, errno);
  for (const std::string_view bytes : pieces) {
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {  // 0: a short write that cannot progress
        const int err = n < 0 ? errno : ENOSPC;
        ::close(fd);
        cannotWrite(path, err);
      }
      done += static_cast<std::size_t>(n);
    }
  }
  if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {  // EINVAL: a file system without fsync (a pipe, /dev/null)
    const int err = errno;
    ::close(fd);
    cannotWrite(path, err);
  }
  if (::close(fd) != 0) cannotWrite(path, errno);
}

void syncFileChecked(const std::string& path, long min_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw OutputError(path + ": was not written (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode)) throw OutputError(path + ": is not a regular file");
  if (st.st_size < min_bytes)
    throw OutputError(path + ": " + std::to_string(st.st_size) + " bytes written, fewer than the " +
                      std::to_string(min_bytes) + " it must hold (disk full?)");
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) cannotWrite(path, errno);
  if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {
    const int err = errno;
    ::close(fd);
    cannotWrite(path, err);
  }
  ::close(fd);
}

}  // namespace mmv
