// jemalloc's options, which it reads from this symbol before the first allocation; compiled
// only where jemalloc is linked (WOBBLE_JEMALLOC; why huge pages: CMakeLists.txt,
// wobble_allocator). Where the kernel has transparent huge pages off, jemalloc uses small ones.
extern "C" {
extern const char* malloc_conf;
const char* malloc_conf = "thp:always,metadata_thp:always";
}
