#pragma once
// How the programs' heap treats large blocks (glibc malloc).

namespace gps {

/// Keeps freed memory in the process for the next allocation instead of returning it to the system:
/// every block comes from the heap (none from its own mmap), and the heap is not trimmed. Loading
/// and preparing a large mesh allocates and frees many blocks of tens of MB (face lists,
/// connectivity, plans, stencils, staging for the GPU); from mmap, each would come back as fresh
/// pages, faulted in and zeroed by the kernel one page at a time. The peak is unchanged; memory freed
/// after it is reused rather than released (the heap's free top goes back past 2 GiB), in the threads'
/// heaps too (a Python call's worker thread, OpenMP's team). Call first thing in main(). Does nothing
/// where the C library has no such settings.
void keep_freed_memory();

/// Keeps up to `bytes` free at the heap's top mapped (glibc's trim threshold), unless an earlier call
/// (keep_freed_memory's included) kept more: a library that wants some kept does not undo a program
/// that keeps everything, which would have every large block of a million-face mesh faulted in again.
void keep_freed_heap_top(int bytes);

/// Asks for `bytes` more than needed whenever a heap grows, and keeps that much free in a thread's heap
/// (glibc's top pad), unless an earlier call (keep_freed_memory's included) asked for more. The pad is
/// address space: its pages are not resident until used.
void pad_heap_top(int bytes);

/// Asks the C library of the program this process runs next (execv) to back its heap with
/// transparent huge pages (glibc's tunable glibc.malloc.hugetlb=1, read only when a program starts),
/// unless the environment already sets that tunable. A program that fills and reads hundreds of MB
/// (the GL commands under a software driver) then faults in and translates memory 2 MiB at a time;
/// its heap's peak may round up to whole huge pages. Does nothing where the C library is not glibc.
void huge_page_heap_for_next_program();

}  // namespace gps
