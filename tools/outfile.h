/* Output files of the tool, replaced atomically: written to a temporary file in the target's
 * directory and renamed over the target only after a complete, flushed and synced write. */
#ifndef BEZSURF_TOOLS_OUTFILE_H
#define BEZSURF_TOOLS_OUTFILE_H

#include <stdio.h>

typedef struct out_file {
    FILE *f;          /* the temporary file */
    char *tmp;        /* its name */
    const char *path; /* the target */
} out_file;

/* Start writing path: 0, or -1 with errno set (EISDIR or EINVAL when path is an existing
 * directory or other non-regular file, which is never replaced; otherwise why the temporary file
 * could not be created). */
int out_open(const char *path, out_file *o);

/* With ok: flush, sync, close and rename over the target; 0 on success. Otherwise, or when any
 * of these fails, remove the temporary file, leave the target untouched and return -1 with errno
 * telling why (with !ok: errno as the caller left it, or EIO). */
int out_close(out_file *o, int ok);

/* Whether path can be written, without writing it: out_open then out_close(o, 0). 0 or -1 with
 * errno set. */
int out_check(const char *path);

#endif
