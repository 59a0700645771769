/* Output files of the tool, replaced atomically: written to a temporary file beside the target and
 * renamed over it only after a complete, flushed and synced write. The temporary file is removed on
 * every failure and on SIGINT, SIGTERM and SIGHUP (one output file at a time). */
#ifndef BEZSURF_TOOLS_OUTFILE_H
#define BEZSURF_TOOLS_OUTFILE_H

#include <stdio.h>

typedef struct out_file {
    FILE *f;          /* the temporary file; NULL once out_hold() closed it */
    char *tmp;        /* its name; NULL when nothing is open */
    char *target;     /* what is replaced: path, or the final target of a symbolic link */
    const char *path; /* the name given */
    const char *why;  /* after a failed out_open: the reason when errno cannot tell it, else NULL */
} out_file;

/* Start writing path: 0, or -1 with errno set (and o->why for an empty name or a symbolic link to
 * a missing file). A symbolic link is written through: the file it finally names is replaced and
 * the link stays. Refused: an existing directory (EISDIR) or other non-regular file (EINVAL), which
 * is never replaced; an existing file the user may not write (access(W_OK): EACCES, EROFS), as cp
 * refuses it; a directory where the temporary file cannot be made. */
int out_open(const char *path, out_file *o);

/* With ok: flush, sync, close and rename over the target (then sync its directory, best effort);
 * 0 on success. Otherwise, or when any of these fails, remove the temporary file, leave the target
 * untouched and return -1 with errno telling why (with !ok: errno as the caller left it, or EIO).
 * Nothing open (o->tmp NULL): returns 0 with ok, else -1. */
int out_close(out_file *o, int ok);

/* For a writer that takes a file name and makes a temporary file of its own beside it (the
 * library's writers): close o->f so that the writer may replace o->tmp, and hold SIGINT, SIGTERM
 * and SIGHUP until out_release(). A signal that comes meanwhile waits for the writer to finish or
 * fail (its own temporary file gone either way) and then removes o->tmp. */
void out_hold(out_file *o);
void out_release(void);

#endif
