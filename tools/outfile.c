/* Atomic output files: see outfile.h. */
#define _POSIX_C_SOURCE 200809L

#include "outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int out_open(const char *path, out_file *o)
{
    o->f = NULL;
    o->tmp = NULL;
    o->path = path;
    struct stat old;
    int exists = stat(path, &old) == 0;
    if (exists && !S_ISREG(old.st_mode)) {
        errno = S_ISDIR(old.st_mode) ? EISDIR : EINVAL;
        return -1;
    }
    /* "<directory of path>/.bezsurf-XXXXXX": mkstemp picks a free name */
    const char *slash = strrchr(path, '/');
    size_t dir_len = slash ? (size_t)(slash - path) + 1 : 0;
    static const char name[] = ".bezsurf-XXXXXX";
    o->tmp = malloc(dir_len + sizeof name);
    if (o->tmp == NULL) {
        errno = ENOMEM;
        return -1;
    }
    memcpy(o->tmp, path, dir_len);
    memcpy(o->tmp + dir_len, name, sizeof name);
    int fd = mkstemp(o->tmp);
    if (fd >= 0) {
        /* the permissions fopen would give: the old file's, or 0666 less the umask */
        mode_t mode = old.st_mode & 07777;
        if (!exists) {
            mode_t mask = umask(0);
            umask(mask);
            mode = 0666 & ~mask;
        }
        (void)fchmod(fd, mode);
        o->f = fdopen(fd, "wb");
    }
    if (o->f == NULL) {
        int e = errno;
        if (fd >= 0) {
            close(fd);
            unlink(o->tmp);
        }
        free(o->tmp);
        o->tmp = NULL;
        errno = e;
        return -1;
    }
    return 0;
}

int out_close(out_file *o, int ok)
{
    int e = ok ? 0 : (errno ? errno : EIO);
    if (ok && (fflush(o->f) != 0 || ferror(o->f)))
        ok = 0, e = errno ? errno : EIO;
    if (ok && fsync(fileno(o->f)) != 0 && errno != EINVAL)
        ok = 0, e = errno;
    if (fclose(o->f) != 0 && ok)
        ok = 0, e = errno;
    o->f = NULL;
    if (ok && rename(o->tmp, o->path) != 0)
        ok = 0, e = errno;
    if (!ok)
        unlink(o->tmp);
    free(o->tmp);
    o->tmp = NULL;
    if (!ok)
        errno = e;
    return ok ? 0 : -1;
}

int out_check(const char *path)
{
    out_file o;
    if (out_open(path, &o) != 0)
        return -1;
    errno = 0;
    out_close(&o, 0);
    return 0;
}
