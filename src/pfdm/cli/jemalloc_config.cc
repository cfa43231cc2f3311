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
// 2 MB.
//
// oversize_threshold:0 puts every allocation in those arenas.  By default
// jemalloc serves blocks over 8 MB from an arena of their own, where a
// freed block's pages serve no smaller allocation: the point readers' 48 MB
// line buffer (fast-cpp-csv-parser's three 16 MB blocks) was freed before
// frame 0 and lay idle there, while frame 0's first factorizations faulted
// in fresh pages, 4 KB at a time: 1,070 faults in a 2,000-tag frame 0,
// against 40 with this setting.  In a fresh `pfdm fit` (one core, gnuplot
// loading on the other) frame 0 took 61 ms against a later frame's 16, and
// 43 ms with it; the faults of the two processes slow each other (31 and
// 42 ms when gnuplot does not load meanwhile).
//
// MALLOC_CONF in the environment still overrides these.
#ifdef PFDM_JEMALLOC
extern "C" {
// Read by jemalloc at its first allocation.
const char* malloc_conf =
    "thp:always,metadata_thp:auto,dirty_decay_ms:-1,muzzy_decay_ms:-1,"
    "oversize_threshold:0";
}
#endif
