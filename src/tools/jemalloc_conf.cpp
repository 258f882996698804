// jemalloc's settings for the kvd tool, read when the allocator starts
// (MALLOC_CONF in the environment still overrides them). Transparent huge
// pages for the heap: a run's tables, logs and certificates are hundreds of
// MiB touched at random (a lookup in the table of certificates is one
// cache miss, and one TLB miss with 4 KiB pages), and 2 MiB pages took a
// sixth to a quarter off whole runs for a tenth more peak memory (README,
// Dependencies). Compiled only when the tool is linked with jemalloc.
extern "C" {
// The name and type jemalloc looks for (an unprefixed build, as Debian's).
// NOLINTNEXTLINE(readability-identifier-naming)
const char* malloc_conf = "thp:always";
}
