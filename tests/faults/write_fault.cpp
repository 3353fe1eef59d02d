/* A write-failure shim for the file-system fault harness (tests/faults/fault_test.cpp),
 * loaded with LD_PRELOAD into mmvlab (C linkage; built by tests/CMakeLists.txt). It counts the write calls that go to regular
 * files (write, pwrite, writev: ours, and the libraries' that call them: the video
 * encoder's) and fails one of them:
 *
 *   MMVLAB_FAULT=count          count only; at exit the count goes to MMVLAB_FAULT_REPORT
 *   MMVLAB_FAULT=enospc:N       the Nth such write fails with ENOSPC (a full disk)
 *   MMVLAB_FAULT=eio:N          ... with EIO (a failing device)
 *   MMVLAB_FAULT=short:N        ... writes half its bytes and reports that (a short write)
 *
 * From the Nth on, ENOSPC and EIO keep failing every later write (a disk stays full);
 * fsync fails the same way once the fault has fired. Writes to pipes, terminals and
 * devices (stdout to a pipe, /dev/null) are not counted; stdout to a file is.
 */
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

extern "C" {

static ssize_t (*real_write)(int, const void*, size_t);
static ssize_t (*real_pwrite)(int, const void*, size_t, off_t);
static ssize_t (*real_writev)(int, const struct iovec*, int);
static int (*real_fsync)(int);
static int (*real_fdatasync)(int);

enum Mode { kOff, kCount, kEnospc, kEio, kShort };
static Mode mode = kOff;
static long target = 0;
static long count = 0;
static int fired = 0;

static void setup(void) {
  static int done = 0;
  if (done) return;
  done = 1;
  real_write = reinterpret_cast<ssize_t (*)(int, const void*, size_t)>(dlsym(RTLD_NEXT, "write"));
  real_pwrite = reinterpret_cast<ssize_t (*)(int, const void*, size_t, off_t)>(dlsym(RTLD_NEXT, "pwrite"));
  real_writev = reinterpret_cast<ssize_t (*)(int, const struct iovec*, int)>(dlsym(RTLD_NEXT, "writev"));
  real_fsync = reinterpret_cast<int (*)(int)>(dlsym(RTLD_NEXT, "fsync"));
  real_fdatasync = reinterpret_cast<int (*)(int)>(dlsym(RTLD_NEXT, "fdatasync"));
  const char* f = std::getenv("MMVLAB_FAULT");
  if (!f) return;
  if (strcmp(f, "count") == 0) mode = kCount;
  else if (strncmp(f, "enospc:", 7) == 0) mode = kEnospc, target = atol(f + 7);
  else if (strncmp(f, "eio:", 4) == 0) mode = kEio, target = atol(f + 4);
  else if (strncmp(f, "short:", 6) == 0) mode = kShort, target = atol(f + 6);
}

static int regular(int fd) {
  struct stat st;
  return fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
}

/* 0: go ahead; >0: write only that many bytes; -1: fail (errno set). */
static long decide(int fd, size_t n) {
  setup();
  if (mode == kOff || !regular(fd)) return 0;
  ++count;
  if (mode == kCount) return 0;
  if (count < target && !fired) return 0;
  if (mode == kShort) {
    if (count != target) return 0;
    fired = 1;
    return n > 1 ? static_cast<long>(n / 2) : 0;
  }
  fired = 1;
  errno = mode == kEnospc ? ENOSPC : EIO;
  return -1;
}

__attribute__((visibility("default"))) ssize_t write(int fd, const void* buf, size_t n) {
  const long d = decide(fd, n);
  if (d < 0) return -1;
  return real_write(fd, buf, d > 0 ? static_cast<size_t>(d) : n);
}

__attribute__((visibility("default"))) ssize_t pwrite(int fd, const void* buf, size_t n, off_t off) {
  const long d = decide(fd, n);
  if (d < 0) return -1;
  return real_pwrite(fd, buf, d > 0 ? static_cast<size_t>(d) : n, off);
}
__attribute__((visibility("default"))) ssize_t pwrite64(int fd, const void* buf, size_t n, off_t off) { return pwrite(fd, buf, n, off); }

__attribute__((visibility("default"))) ssize_t writev(int fd, const struct iovec* iov, int cnt) {
  size_t n = 0;
  for (int i = 0; i < cnt; ++i) n += iov[i].iov_len;
  const long d = decide(fd, n);
  if (d < 0) return -1;
  if (d > 0 && cnt > 0) return real_write(fd, iov[0].iov_base, iov[0].iov_len < static_cast<size_t>(d) ? iov[0].iov_len : static_cast<size_t>(d));
  return real_writev(fd, iov, cnt);
}

/* A flush to the disk fails once a full disk or a failing device has shown itself. */
static int syncThrough(int fd, int (*real)(int)) {
  setup();
  if (fired && (mode == kEnospc || mode == kEio) && regular(fd)) {
    errno = mode == kEnospc ? ENOSPC : EIO;
    return -1;
  }
  return real(fd);
}

__attribute__((visibility("default"))) int fsync(int fd) {
  return syncThrough(fd, real_fsync);
}

__attribute__((visibility("default"))) int fdatasync(int fd) {
  return syncThrough(fd, real_fdatasync);
}

__attribute__((destructor)) static void report(void) {
  setup();
  const char* path = getenv("MMVLAB_FAULT_REPORT");
  if (mode != kCount || !path) return;
  const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return;
  char text[32];
  const int len = snprintf(text, sizeof text, "%ld\n", count);
  if (len > 0) if (real_write(fd, text, static_cast<size_t>(len)) < 0) { /* nothing to do: the harness sees no count */ }
  close(fd);
}

}  // extern "C"
