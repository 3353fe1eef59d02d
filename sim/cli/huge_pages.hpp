#pragma once
/// A render's supersampled frame buffers (ours and llvmpipe's, some 100 MB for a 1280x720
/// still at 3x) are zeroed page by page as they are first touched; on the 4 kB pages of a
/// virtual machine those faults were a third of `mmvlab render`'s whole process
/// (docs/benchmarks.md, 2026-11-28). glibc's malloc asks for transparent huge pages on
/// its large blocks when the tunable glibc.malloc.hugetlb=1 is set, which it reads only at
/// start-up; Mesa's buffers are malloc'd, so the tunable must be there before the
/// process starts. Only render: the second start costs about 20 ms (half of a
/// `modes`); the other commands get huge pages on the heap in-process (keepFreedMemory).

namespace mmv::cli {

/// Executes this program again (/proc/self/exe, the same arguments and pid) with
/// GLIBC_TUNABLES extended by glibc.malloc.hugetlb=1, unless it is already there or
/// MMVLAB_NO_HUGE_PAGES is set; returns only when it does not (also when the exec fails:
/// the render then runs on small pages). Call it before any work or output.
void reexecWithHugePages(char** argv);

/// Keeps freed memory in the process for the next allocation of its size: glibc's malloc
/// gives a block of 128 kB or more back to the kernel when it is freed (it was mapped for
/// it) and trims the heap's top past 128 kB, so a study that builds one dense matrix after
/// another (a 512-state model's are 2 MB each) takes every page of each as a fresh fault.
/// Blocks up to 256 MB come from the heap and the heap is not trimmed below 1 GB: the peak
/// memory is the same, it is only not returned before the process ends (`frf --segments
/// 64` 0.40 -> 0.34 s, `rom` 0.57 -> 0.49 s, `modes --segments 1024` 0.62 -> 0.57 s).
/// Then the heap's first 128 MB are advised for transparent huge pages (madvise on a
/// block malloc'd and freed at once: nothing is touched, and the address space stays the
/// heap's), what glibc.malloc.hugetlb=1 does without a second start: each 2 MB is one
/// fault instead of 512 (`rom --segments 64` 9,300 -> 1,300 faults, 0.24 -> 0.15 s;
/// docs/benchmarks.md). Not where GLIBC_TUNABLES already sets hugetlb (render's second
/// start) or MMVLAB_NO_HUGE_PAGES is set. Call it first; the sanitizers' allocators
/// ignore it.
void keepFreedMemory();

}  // namespace mmv::cli
