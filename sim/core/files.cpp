#include "sim/core/files.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

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

}  // namespace mmv
