/* tls_module.c - a shared library with one small thread-local block, dlopened by tls_probe.c.
 * A dlopened library's thread-local storage is reached through __tls_get_addr; when it does
 * not fit glibc's spare static TLS, glibc gives it a block from malloc, which under
 * AddressSanitizer is a heap chunk. 40 bytes keeps the chunk in the allocator's 64-byte size
 * class, whose chunks can start on a page boundary. */
__thread char idview_tls_block[40];

char* idview_tls_touch(void) {
    idview_tls_block[0] = 1;
    return idview_tls_block;
}
