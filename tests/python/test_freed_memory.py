"""Importing gpsurf keeps freed memory in the process, as gpsurf's programs do
(core/support/freed_memory.h): a large block comes from the heap, not from a mapping of its own, so
that the blocks one call frees serve the next instead of being mapped and zeroed afresh."""
import ctypes
import ctypes.util
import platform
import threading

import pytest

import gpsurf  # noqa: F401  (its import is what is tested)


class MallInfo2(ctypes.Structure):
    _fields_ = [(name, ctypes.c_size_t) for name in
                ("arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks", "uordblks", "fordblks",
                 "keepcost")]


def glibc():
    if platform.system() != "Linux" or platform.libc_ver()[0] != "glibc":
        pytest.skip("glibc's malloc settings only")
    libc = ctypes.CDLL(ctypes.util.find_library("c"))
    if not hasattr(libc, "mallinfo2"):
        pytest.skip("glibc before 2.33 has no mallinfo2")
    libc.mallinfo2.restype = MallInfo2
    libc.malloc.restype = ctypes.c_void_p
    libc.malloc.argtypes = [ctypes.c_size_t]
    libc.free.argtypes = [ctypes.c_void_p]
    return libc


def test_a_large_block_comes_from_the_heap_and_stays_there_when_freed():
    libc = glibc()
    size = 48 << 20  # far past glibc's default threshold for a mapping of its own (128 KiB to 32 MiB)
    mapped_before = libc.mallinfo2().hblkhd
    block = libc.malloc(size)
    assert block
    ctypes.memset(block, 1, size)
    assert libc.mallinfo2().hblkhd - mapped_before < size, "the block was mapped on its own"
    libc.free(block)
    assert libc.mallinfo2().fordblks >= size, "the freed block went back to the system"


def test_a_worker_threads_freed_heaps_stay_in_the_process():
    """A call runs on a worker thread, whose blocks glibc serves from heaps of 64 MiB it unmaps once
    empty unless told otherwise: the next call would fault all of its memory in again."""
    libc = glibc()
    size = 40 << 20
    heap = {}

    def work():
        blocks = [libc.malloc(size) for _ in range(3)]  # more than one of the thread's heaps
        for block in blocks:
            assert block
            ctypes.memset(block, 1, size)
        heap["held"] = libc.mallinfo2().arena
        for block in blocks:
            libc.free(block)
        heap["freed"] = libc.mallinfo2().arena

    worker = threading.Thread(target=work)
    worker.start()
    worker.join()
    assert heap["freed"] == heap["held"], "a freed heap of the thread went back to the system"
