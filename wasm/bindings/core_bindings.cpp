// Embind glue shared by every capability: memory statistics of the wasm heap.
#include <emscripten/bind.h>
#include <malloc.h>

namespace {
// Bytes currently allocated by malloc (dlmalloc's in-use count): leak checks compare it
// before and after create/dispose cycles.
double heap_used() { return double(mallinfo().uordblks); }
}  // namespace

EMSCRIPTEN_BINDINGS(splinekit_core) { emscripten::function("heapUsed", &heap_used); }
