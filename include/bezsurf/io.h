/**
 * @file
 * libbezsurf input and output: the .bpt text format, OBJ free-form surfaces, IGES B-spline
 * surfaces and the built-in tea set.
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
 * line and column 0; from 1.1 also BS_ERR_UNSUPPORTED from the OBJ reader, with the position). `line` and `column` are 1-based; the column counts bytes from the start of the
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
 * The text need not be NUL-terminated; one final NUL is ignored (since 1.2: so the size
 * bs_surface_write_bpt() reports, which counts it, can be passed as len), a NUL byte elsewhere is
 * an error. Numbers are read in the
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
 * @brief Parse the free-form surfaces of Wavefront OBJ text (version 3.0) into a new surface of 3-D
 * patches.
 * Read: `v x y z [w]`, `cstype [rat] bezier|bspline`, `deg`, `surf s0 s1 t0 t1 v[/vt[/vn]] ...`
 * (u varies fastest in the list), `parm u|v ...`, `end`, negative (relative) vertex indices, `\`
 * line continuation and `#` comments. A Bezier surface with several parameter values per direction
 * gives one patch per segment; a B-spline surface one patch per knot span (through
 * bs_surface_add_bspline()) of its `surf` parameter range (spans the range cuts are cut). Polygons, groups, display and rendering statements, curves and
 * trimming statements are skipped (a trimmed surface is read whole). docs/formats.md gives the
 * exact subset. A text without surfaces gives an empty surface, unless it has polygons or
 * curves (f, l, p, curv, curv2): then, since 1.2, BS_ERR_UNSUPPORTED with err saying how many of
 * each it holds and where the first is (1.1 gave an empty surface). One final NUL is ignored (since
 * 1.2: so the size bs_surface_write_obj() reports, which counts it, can be passed as len).
 * @param[in]  text  the bytes; may be NULL only when len is 0.
 * @param[in]  len   number of bytes.
 * @param[out] err   NULL, or receives the position and reason of the first error on BS_ERR_PARSE
 *                   and BS_ERR_UNSUPPORTED; untouched on success.
 * @param[out] out   receives the new surface (NULL on failure); release with bs_surface_destroy().
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if out is NULL, or text is NULL with len > 0.
 * @return BS_ERR_PARSE if the text is malformed (bad numbers or indices, counts that do not match
 *         the degree and the parameter values, a NUL byte before the last one, non-positive weights of a rational
 *         surface, ...).
 * @return BS_ERR_UNSUPPORTED for a surface of another curve type (bmatrix, cardinal, taylor), or
 *         polygons or curves without any surface (since 1.2).
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.1
 */
BS_API bs_status bs_surface_read_obj(const char *text, size_t len, bs_parse_error *err, bs_surface **out);

/**
 * @brief Read an OBJ file into a new surface (as bs_surface_read_obj() on the file's bytes).
 * @param[in]  path  file name, passed to fopen() unchanged.
 * @param[out] err   NULL, or receives the error position and reason on BS_ERR_PARSE,
 *                   BS_ERR_UNSUPPORTED or BS_ERR_IO.
 * @param[out] out   receives the new surface (NULL on failure).
 * @return BS_OK; BS_ERR_INVALID_ARG if path or out is NULL; BS_ERR_IO if the file cannot be opened
 *         or read, or is larger than 256 MiB; BS_ERR_PARSE; BS_ERR_UNSUPPORTED; BS_ERR_NO_MEMORY.
 * @since 1.1
 */
BS_API bs_status bs_surface_read_obj_file(const char *path, bs_parse_error *err, bs_surface **out);

/**
 * @brief Write a surface as OBJ free-form text into a caller buffer (ask for the size first).
 * Each patch becomes its control vertices (`v`), then `cstype bezier` or `cstype rat bezier`,
 * `deg`, one `surf 0 1 0 1 ...` listing them with u fastest, `parm u 0 1`, `parm v 0 1` and `end`.
 * Numbers are written as in bs_surface_write_bpt(): reading the text gives back every control
 * point and weight bit for bit.
 * @param[in]  s     the surface; its patches must be 3-D (an empty surface writes a comment only).
 * @param[out] buf   NULL to ask for the size, or room for cap bytes receiving the text and a final NUL.
 * @param[in]  cap   bytes buf can hold (ignored when buf is NULL).
 * @param[out] size  receives the number of bytes needed (or written), the final NUL included.
 * @return BS_OK; BS_ERR_INVALID_ARG if s or size is NULL; BS_ERR_DIMENSION if the patches are not
 *         3-D; BS_ERR_SIZE if cap is below the size needed (nothing is written then).
 * @since 1.1
 */
BS_API bs_status bs_surface_write_obj(const bs_surface *s, char *buf, size_t cap, size_t *size);

/**
 * @brief Write a surface as an OBJ file (same text as bs_surface_write_obj(), without the NUL).
 * The file is replaced atomically, as by bs_surface_write_bpt_file(): a temporary file in the same
 * directory, synced and renamed over path only once complete; on failure an existing file is left
 * untouched, and directories, FIFOs and devices are never replaced.
 * @param[in] s     the surface (3-D patches).
 * @param[in] path  file name, created or replaced.
 * @return BS_OK; BS_ERR_INVALID_ARG if s or path is NULL; BS_ERR_DIMENSION; BS_ERR_IO if the file
 *         cannot be written (errno tells why; the old file is kept); BS_ERR_NO_MEMORY.
 * @since 1.1
 */
BS_API bs_status bs_surface_write_obj_file(const bs_surface *s, const char *path);

/**
 * @brief Parse an IGES 5.3 file held in memory: every rational B-spline surface (entity 128) into
 * Bezier patches of a new surface.
 * Fixed 80-column records in the sections S, G, D, P, T; the parameter and record delimiters of
 * the global section; Hollerith strings; `D` exponents. Each entity 128 is cut at its knots (as
 * bs_surface_add_bspline()) and restricted to its parameter range U0 U1 V0 V1; the matrices of
 * the entities 124 its directory entry points to (and theirs) are applied to its control points.
 * Entities 128 that are subordinate (e.g. the base of a trimmed surface) are read all the same,
 * whole; every other entity is skipped. docs/formats.md gives the exact subset. Coordinates are
 * taken in the file's units.
 * @param[in]  text  the bytes; may be NULL only when len is 0 (a parse error: no sections).
 * @param[in]  len   number of bytes.
 * @param[out] err   NULL, or receives the line (the record's line in the file) and column of the
 *                   first error on BS_ERR_PARSE; untouched on success.
 * @param[out] out   receives the new surface (NULL on failure); release with bs_surface_destroy().
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if out is NULL, or text is NULL with len > 0.
 * @return BS_ERR_PARSE if the records, the sections, the directory or an entity 128 or 124 are
 *         malformed (bad numbers, counts that do not match, decreasing knots, non-positive
 *         weights, pointers to nothing, circular transformations, ...).
 * @return BS_ERR_NO_MEMORY if allocation fails.
 * @since 1.1
 */
BS_API bs_status bs_surface_read_iges(const char *text, size_t len, bs_parse_error *err, bs_surface **out);

/**
 * @brief Read an IGES file into a new surface (as bs_surface_read_iges() on the file's bytes).
 * @param[in]  path  file name, passed to fopen() unchanged.
 * @param[out] err   NULL, or receives the error position and reason on BS_ERR_PARSE or BS_ERR_IO.
 * @param[out] out   receives the new surface (NULL on failure).
 * @return BS_OK; BS_ERR_INVALID_ARG if path or out is NULL; BS_ERR_IO if the file cannot be opened
 *         or read, or is larger than 256 MiB; BS_ERR_PARSE; BS_ERR_NO_MEMORY.
 * @since 1.1
 */
BS_API bs_status bs_surface_read_iges_file(const char *path, bs_parse_error *err, bs_surface **out);

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
