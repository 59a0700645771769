/**
 * @file
 * libbezsurf input and output: the .bpt text format and the built-in tea set.
 * Numbers are read and written in the C notation whatever LC_NUMERIC says; the functions may run in
 * any number of threads at once, as long as no thread changes the locale meanwhile.
 * Include <bezsurf.h> rather than this file.
 */
#ifndef BEZSURF_IO_H
#define BEZSURF_IO_H

#include "core.h"
#include "surface.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Where and why parsing failed. Filled only when a reader returns BS_ERR_PARSE (or BS_ERR_IO, with
 * line and column 0). `line` and `column` are 1-based; the column counts bytes from the start of the
 * line. `message` is a NUL-terminated English sentence fragment such as "expected a number".
 * The struct is frozen for version 1. @since 1.0
 */
typedef struct bs_parse_error {
    size_t line;       /**< 1-based line of the first error (0 when there is no position) */
    size_t column;     /**< 1-based byte column of the first error (0 when there is no position) */
    char message[96];  /**< what is wrong, NUL-terminated */
} bs_parse_error;

/**
 * @brief Parse .bpt text held in memory into a new surface of 3-D patches.
 * The text need not be NUL-terminated; a NUL byte inside it is an error. Numbers are read in the
 * C notation whatever the process locale. See docs/bpt-format.md for the grammar, the rational
 * extension and the limits (degrees up to BS_MAX_DEGREE, counts consistent with the input length,
 * finite coordinates, positive finite weights, numbers of at most 400 characters).
 * @param[in]  text  the bytes; may be NULL only when len is 0 (which is a parse error: no count).
 * @param[in]  len   number of bytes.
 * @param[out] err   NULL, or receives the position and reason of the first error on BS_ERR_PARSE;
 *                   untouched on success.
 * @param[out] out   receives the new surface (NULL on failure); release with bs_surface_destroy().
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if out is NULL, or text is NULL with len > 0.
 * @return BS_ERR_PARSE if the text is not a valid .bpt file (truncated, trailing garbage, negative or
 *         absurd counts or degrees, NaN, Inf or out-of-range numbers, non-positive weights).
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_surface_read_bpt(const char *text, size_t len, bs_parse_error *err, bs_surface **out);

/**
 * @brief Read a .bpt file into a new surface (as bs_surface_read_bpt() on the file's bytes).
 * Only regular files are read: a directory, FIFO, device or socket is refused before any byte is
 * read, and opening never waits (a FIFO without a writer does not block).
 * @param[in]  path  file name, passed to open() unchanged.
 * @param[out] err   NULL, or receives the error position and reason on BS_ERR_PARSE or BS_ERR_IO
 *                   (line and column 0 and one of "cannot open the file", "not a regular file (a
 *                   directory)" or (a FIFO, a device, a socket), "cannot read the file", "file
 *                   larger than 256 MiB").
 * @param[out] out   receives the new surface (NULL on failure).
 * @return BS_OK; BS_ERR_INVALID_ARG if path or out is NULL; BS_ERR_IO if the file cannot be opened
 *         or read, is not a regular file, or is larger than 256 MiB (268435456 bytes; a file of
 *         exactly that size is read), with errno set by the failing system call (EISDIR for a
 *         directory, EFBIG for a file too large, 0 for other non-regular files); BS_ERR_PARSE;
 *         BS_ERR_NO_MEMORY.
 * @since 1.0
 */
BS_API bs_status bs_surface_read_bpt_file(const char *path, bs_parse_error *err, bs_surface **out);

/**
 * @brief Write a surface as .bpt text into a caller buffer (ask for the size first).
 * Every number is written with the fewest significant digits (at most 17) that read back to the same
 * double, with '.' as decimal point whatever the locale: reading the text gives back every control
 * point and weight bit for bit. Rational patches use the extension described in docs/bpt-format.md.
 * @param[in]  s     the surface; its patches must be 3-D (an empty surface writes "0").
 * @param[out] buf   NULL to ask for the size, or room for cap bytes receiving the text and a final NUL.
 * @param[in]  cap   bytes buf can hold (ignored when buf is NULL).
 * @param[out] size  receives the number of bytes needed (or written), the final NUL included.
 * @return BS_OK; BS_ERR_INVALID_ARG if s or size is NULL; BS_ERR_DIMENSION if the patches are not
 *         3-D; BS_ERR_SIZE if cap is below the size needed (nothing is written then).
 * @since 1.0
 */
BS_API bs_status bs_surface_write_bpt(const bs_surface *s, char *buf, size_t cap, size_t *size);

/**
 * @brief Write a surface as a .bpt file (same text as bs_surface_write_bpt(), without the NUL).
 * The file is replaced atomically: the text goes to a new temporary file in the same directory
 * (`.bezsurf-<16 hex digits>.tmp`), which is flushed, synced to disk and then renamed over path.
 * On any failure the temporary file is removed and an existing file at path is left untouched.
 * A replaced file keeps its permission bits; a new one gets 0666 less the umask. A symbolic link
 * at path is replaced by the file, not followed. An existing directory, FIFO or device at path is
 * never replaced (BS_ERR_IO).
 * @param[in] s     the surface (3-D patches).
 * @param[in] path  file name.
 * @return BS_OK; BS_ERR_INVALID_ARG if s or path is NULL; BS_ERR_DIMENSION; BS_ERR_IO if path is
 *         not a regular file or the file cannot be created, written, synced or renamed, with errno
 *         telling why (e.g. ENOSPC, EFBIG, EACCES; EISDIR for a directory, EINVAL for another
 *         non-regular file); BS_ERR_NO_MEMORY.
 * @since 1.0
 */
BS_API bs_status bs_surface_write_bpt_file(const bs_surface *s, const char *path);

/**
 * @brief Create one of the built-in surfaces: "teapot" (32 bicubic patches, Z up), "teacup" (26,
 * Y up) or "teaspoon" (16, Y up), Newell's tea set, parsed from text compiled into the library.
 * @param[in]  name  the surface's name (case-sensitive); see bs_builtin_name().
 * @param[out] out   receives the new surface (NULL on failure).
 * @return BS_OK; BS_ERR_INVALID_ARG if name or out is NULL or name is unknown; BS_ERR_NO_MEMORY.
 * @since 1.0
 */
BS_API bs_status bs_surface_create_builtin(const char *name, bs_surface **out);

/**
 * @brief Name of built-in surface i, for listing them: i = 0, 1, 2, ... until NULL.
 * @param[in] i  index.
 * @return a static string, or NULL when i is not below the number of built-in surfaces.
 * @since 1.0
 */
BS_API const char *bs_builtin_name(size_t i);

#ifdef __cplusplus
}
#endif

#endif
