#pragma once
/// A render's supersampled frame buffers (ours and llvmpipe's, some 100 MB for a 1280x720
/// still at 3x) are zeroed page by page as they are first touched; on the 4 kB pages of a
/// virtual machine those faults were a third of `mmvlab render`'s whole process
/// (docs/benchmarks.md, 2026-11-28). glibc's malloc asks for transparent huge pages on
/// its large blocks when the tunable glibc.malloc.hugetlb=1 is set, which it reads only at
/// start-up; Mesa's buffers are malloc'd, so the tunable must be there before the
/// process starts.

namespace mmv::cli {

/// Executes this program again (/proc/self/exe, the same arguments and pid) with
/// GLIBC_TUNABLES extended by glibc.malloc.hugetlb=1, unless it is already there or
/// MMVLAB_NO_HUGE_PAGES is set; returns only when it does not (also when the exec fails:
/// the render then runs on small pages). Call it before any work or output.
void reexecWithHugePages(char** argv);

}  // namespace mmv::cli
