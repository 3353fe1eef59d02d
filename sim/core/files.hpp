#pragma once
// Reading a user's input file (a scene, a sweep spec, a table profile, a run's record)
// whole and safely: only a regular file of bounded size is opened, so a directory, a
// device that never ends (/dev/zero), a FIFO that blocks until a writer comes, or a
// file too large to be what it claims is refused before a byte is read.
#include <string>

namespace mmv {

enum class InputFileProblem { None, CannotOpen, NotRegular, TooLarge };

/// True with the file's bytes in `contents`; else false with `why`, a phrase that
/// completes "PATH: ..." ("No such file or directory", "is a directory", "is not a
/// regular file (a device, FIFO or socket)", "17000000 bytes, above the limit of
/// 16777216 bytes"), and `problem` saying which kind it is.
bool readInputFile(const std::string& path, long max_bytes, std::string& contents, std::string& why,
                   InputFileProblem* problem = nullptr);

}  // namespace mmv
