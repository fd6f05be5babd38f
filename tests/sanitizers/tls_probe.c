/* tls_probe.c MODULE - shows that the sanitizer pass's options survive LeakSanitizer's exit
 * check when a dynamic thread-local block sits 16 bytes past a page boundary. Built and run by
 * scripts/sanitize-tests.sh with -fsanitize=address and the pass's ASAN_OPTIONS.
 *
 * Why: GCC 12's sanitizer runtime intercepts __tls_get_addr and, for a block whose address is
 * 16 modulo 4096, takes the two words before it for the header that glibc 2.19-2.24 wrote
 * there (start and size of the block). Since glibc 2.25 there is no such header: under ASan
 * those words are the chunk's own header, so the runtime records a nonsense range, and at exit
 * the leak check scans it and its tracer dies ("Tracer caught signal 11"). Whether a block
 * lands on that offset depends on the order of allocations, so it struck idview's tests at
 * random (json_units, once in a CI run). Here the heap is filled up to the chunk before a page
 * boundary first, so the block lands there every time.
 *
 * Exit 0: the block landed at the offset and the process ended normally. Exit 3: the block
 * could not be placed there, so nothing was shown (a failure, never a pass). A crash in the
 * leak check exits with the sanitizer's exit code. */
#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

enum { kPage = 4096, kHeader = 16, kClass = 64, kMostFills = 1 << 16 };

/* Reachable to the end, so LeakSanitizer reports none of them (external, so the compiler keeps
 * the stores). */
void* tls_probe_filler[kMostFills];

int main(int argc, char** argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: tls_probe MODULE.so\n");
        return 2;
    }
    void* module = dlopen(argv[1], RTLD_NOW);
    if (!module) {
        fprintf(stderr, "tls_probe: %s\n", dlerror());
        return 2;
    }
    char* (*touch)(void) = (char* (*)(void))dlsym(module, "idview_tls_touch");
    if (!touch) {
        fprintf(stderr, "tls_probe: %s has no idview_tls_touch\n", argv[1]);
        return 2;
    }
    /* Stop once the last chunk taken is the one just before a page boundary: the next chunk
     * of the size class, which glibc takes for the block, starts on the boundary. */
    int fills = 0;
    while (fills < kMostFills) {
        void* chunk = malloc(40);
        tls_probe_filler[fills++] = chunk;
        if ((uintptr_t)chunk % kPage == kPage - kClass + kHeader) break;
    }
    uintptr_t block = (uintptr_t)touch();
    if (block % kPage != kHeader) {
        fprintf(stderr, "tls_probe: the block landed at %#lx, not 16 past a page (%d fills)\n",
                (unsigned long)block, fills);
        return 3;
    }
    printf("tls_probe: thread-local block at %#lx, 16 bytes past a page\n", (unsigned long)block);
    return 0;
}
