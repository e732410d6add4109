// jemalloc's options, which it reads from this symbol before the first allocation (it is linked
// only where the program is: CMakeLists.txt, wobble_allocator). Huge pages: a solve's heap
// grows to about a megabyte, which 4 KiB pages fault in one by one (~15 us each on a virtual
// machine, 3 ms of a three-atom-molecule solve) and a 2 MiB page in one fault. Where the
// kernel has transparent huge pages off, jemalloc uses small pages as before.
extern "C" {
extern const char* malloc_conf;
const char* malloc_conf = "thp:always,metadata_thp:always";
}
