/* keep_loaded.c - LD_PRELOADed by scripts/sanitize-tests.sh (never linked into idview).
 *
 * The Vulkan loader dlclose()s lavapipe (libvulkan_lvp.so, with libLLVM) and the validation
 * layer at vkDestroyInstance, before LeakSanitizer's exit-time check. Their allocations then
 * show as "(<unknown module>)" frames, which no suppression can match, and memory that their
 * still-reachable globals held looks leaked. In sanitized processes only (those that have
 * __asan_init), this dlopens each library named in IDVIEW_SAN_KEEP_LOADED (colon-separated)
 * with RTLD_NODELETE | RTLD_LOCAL: the loader later gets the same object, nothing is
 * interposed, and it stays mapped until exit. bash, od, grep... are left untouched. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

__attribute__((constructor)) static void idview_keep_loaded(void) {
    const char* list = getenv("IDVIEW_SAN_KEEP_LOADED");
    if (!list || !dlsym(RTLD_DEFAULT, "__asan_init")) return;
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", list);
    for (char* save = NULL, *lib = strtok_r(buf, ":", &save); lib; lib = strtok_r(NULL, ":", &save))
        if (!dlopen(lib, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE))
            fprintf(stderr, "keep_loaded: %s\n", dlerror());
}
