#pragma once
// Files in and out. Reading a user's input file (a scene, a sweep spec, a table
// profile, a run's record) whole and safely: only a regular file of bounded size is opened, so a directory, a
// device that never ends (/dev/zero), a FIFO that blocks until a writer comes, or a
// file too large to be what it claims is refused before a byte is read. Writing an
// output file with every step checked (writeFileChecked, syncFileChecked).
#include <string>
#include <string_view>
#include <vector>

namespace mmv {

enum class InputFileProblem { None, CannotOpen, NotRegular, TooLarge };

/// True with the file's bytes in `contents`; else false with `why`, a phrase that
/// completes "PATH: ..." ("No such file or directory", "is a directory", "is not a
/// regular file (a device, FIFO or socket)", "17000000 bytes, above the limit of
/// 16777216 bytes"), and `problem` saying which kind it is.
bool readInputFile(const std::string& path, long max_bytes, std::string& contents, std::string& why,
                   InputFileProblem* problem = nullptr);

/// Writes `bytes` to `path` (created, or truncated), checking every write, the flush to
/// the disk (fsync) and the close, so a full disk, an I/O error or a short write is an
/// OutputError ("PATH: cannot write: No space left on device") and never a short file
/// with exit 0.
void writeFileChecked(const std::string& path, std::string_view bytes);
/// The same for a file made of pieces, written in order (a .mat file's headers between
/// its matrices' data, written from the matrices themselves).
void writeFileChecked(const std::string& path, const std::vector<std::string_view>& pieces);

/// Flushes a file a library wrote (a PNG, a .mat, a video) to the disk and checks it is
/// there, regular and at least `min_bytes` long; an OutputError otherwise.
void syncFileChecked(const std::string& path, long min_bytes = 1);

}  // namespace mmv
