/* Deflate compression (RFC 1951) with no dependency: LZ77 over a 32 KiB window with hash chains
 * and lazy matching, then per block the smallest of a dynamic Huffman block (codes limited to 15
 * bits), a fixed Huffman block and stored blocks. */
#ifndef BEZSURF_TOOLS_DEFLATE_H
#define BEZSURF_TOOLS_DEFLATE_H

#include <stddef.h>

/* Compress n bytes (src may be NULL when n is 0) into a raw deflate stream, ending with a final
 * block. Returns a malloc'd buffer of *out_n bytes for the caller to free, or NULL if out of
 * memory. */
unsigned char *deflate_compress(const unsigned char *src, size_t n, size_t *out_n);

#endif
