// The allocator's settings for the executables that link jemalloc: the CLI
// and the benchmarks (CMake option PFDM_JEMALLOC).  Not the library: the
// Python module and other hosts keep their own allocator.
//
// On the 2-core VMs pfdm is measured on, a page fault costs about 11 us,
// some fifty times a bare machine's, and glibc's malloc gives a large
// block's pages back to the kernel when it is freed: every frame's large
// vectors and every output file's buffer faulted their pages in again, a
// quarter of a 50,000-tag job.  jemalloc keeps freed pages for reuse (no
// decay: a job is short) and asks for transparent huge pages, one fault per
// 2 MB.  MALLOC_CONF in the environment still overrides these.
#ifdef PFDM_JEMALLOC
extern "C" {
// Read by jemalloc at its first allocation.
const char* malloc_conf =
    "thp:always,metadata_thp:auto,dirty_decay_ms:-1,muzzy_decay_ms:-1";
}
#endif
