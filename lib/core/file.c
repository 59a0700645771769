/* Files the library writes: a temporary file beside the target, renamed over it only after a
 * complete, checked write, so that the target holds either its old content or the new one. */
#define _POSIX_C_SOURCE 200809L // NOLINT(bugprone-reserved-identifier,cert-dcl37-c,cert-dcl51-cpp): POSIX feature-test macro

#include "core/internal.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define TMP_PREFIX ".bezsurf-"
#define TMP_DIGITS 16
#define TMP_SUFFIX ".tmp"
#define TMP_TRIES 64

static uint64_t mix(uint64_t x)
{
    x += 0x9E3779B97F4A7C15u;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9u;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBu;
    return x ^ (x >> 31);
}

/* Create "<dir of path>/.bezsurf-<16 hex digits>.tmp" exclusively (mode 0666 less the umask, as
 * fopen would); fd on success, -1 with errno set. Names come from the process id, the clock and a
 * stack address (no shared state), and a taken name is simply tried again with the next one. */
static int create_tmp(const char *path, char *tmp)
{
    const char *slash = strrchr(path, '/');
    size_t dir_len = slash ? (size_t)(slash - path) + 1 : 0;
    memcpy(tmp, path, dir_len);
    char *name = tmp + dir_len;
    struct timespec now = {0, 0};
    (void)clock_gettime(CLOCK_REALTIME, &now);
    uint64_t seed = mix((uint64_t)getpid() ^ mix((uint64_t)now.tv_sec) ^ (uint64_t)now.tv_nsec ^
                        (uint64_t)(uintptr_t)&now);
    for (int attempt = 0; attempt < TMP_TRIES; attempt++) {
        uint64_t x = mix(seed + (uint64_t)attempt);
        memcpy(name, TMP_PREFIX, sizeof TMP_PREFIX - 1);
        char *d = name + sizeof TMP_PREFIX - 1;
        for (int k = 0; k < TMP_DIGITS; k++)
            d[k] = "0123456789abcdef"[(x >> (4 * k)) & 15u];
        memcpy(d + TMP_DIGITS, TMP_SUFFIX, sizeof TMP_SUFFIX); /* with the NUL */
        int fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    return -1; /* errno is EEXIST */
}

bs_status bsi_out_open(const char *path, bsi_out_file *o)
{
    o->f = NULL;
    o->tmp = NULL;
    o->path = path;
    struct stat old;
    int exists = stat(path, &old) == 0;
    if (exists && !S_ISREG(old.st_mode)) {
        /* never replace a directory, a device or a FIFO (and never block opening one) */
        errno = S_ISDIR(old.st_mode) ? EISDIR : EINVAL;
        return BS_ERR_IO;
    }
    size_t len = strlen(path);
    o->tmp = malloc(len + sizeof TMP_PREFIX + TMP_DIGITS + sizeof TMP_SUFFIX);
    if (o->tmp == NULL)
        return BS_ERR_NO_MEMORY;
    int fd = create_tmp(path, o->tmp);
    if (fd < 0) {
        int e = errno;
        free(o->tmp);
        o->tmp = NULL;
        errno = e;
        return BS_ERR_IO;
    }
    if (exists) /* the new file keeps the old one's permissions; best effort */
        (void)fchmod(fd, old.st_mode & 07777);
    o->f = fdopen(fd, "wb");
    if (o->f == NULL) {
        int e = errno;
        (void)close(fd);
        (void)unlink(o->tmp);
        free(o->tmp);
        o->tmp = NULL;
        errno = e;
        return BS_ERR_IO;
    }
    return BS_OK;
}

/* Make a rename in the directory of tmp durable: fsync the directory (best effort: some file
 * systems refuse, and the data is already safe; the new name is what a crash could lose). tmp is
 * cut to its directory, so nothing is allocated. */
static void sync_dir(char *tmp)
{
    char *slash = strrchr(tmp, '/');
    const char *dir = ".";
    if (slash != NULL) {
        slash[1] = '\0';
        dir = tmp;
    }
    int fd = open(dir, O_RDONLY);
    if (fd >= 0) {
        (void)fsync(fd);
        (void)close(fd);
    }
}

bs_status bsi_out_close(bsi_out_file *o, int ok)
{
    int e = ok ? 0 : (errno ? errno : EIO);
    if (ok && (fflush(o->f) != 0 || ferror(o->f)))
        ok = 0, e = errno ? errno : EIO;
    /* the data must be on disk before the name points at it, or a crash could leave an empty file */
    if (ok && fsync(fileno(o->f)) != 0 && errno != EINVAL)
        ok = 0, e = errno;
    if (fclose(o->f) != 0 && ok)
        ok = 0, e = errno;
    o->f = NULL;
    if (ok && rename(o->tmp, o->path) != 0)
        ok = 0, e = errno;
    if (!ok)
        (void)unlink(o->tmp);
    else
        sync_dir(o->tmp);
    free(o->tmp);
    o->tmp = NULL;
    if (!ok)
        errno = e;
    return ok ? BS_OK : BS_ERR_IO;
}
