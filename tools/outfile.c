/* Atomic output files: see outfile.h. */
#define _XOPEN_SOURCE 700 /* POSIX 2008 with realpath */

#include "outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- removal on a signal ---- */

#define CAUGHT 3
static const int caught[CAUGHT] = {SIGINT, SIGTERM, SIGHUP};
static struct sigaction previous[CAUGHT];
/* The temporary file's name, copied before the handler may need it: a handler may only call
 * async-signal-safe functions (unlink, raise), so it reads nothing that malloc made. */
static char pending[PATH_MAX];
static volatile sig_atomic_t armed;

static void on_signal(int sig)
{
    if (armed)
        (void)unlink(pending);
    /* SA_RESETHAND put back the default action: raised again when the handler returns, the signal
     * ends the process as it would have, and the exit status shows it */
    (void)raise(sig);
}

static void caught_set(sigset_t *set)
{
    sigemptyset(set);
    for (int k = 0; k < CAUGHT; k++)
        sigaddset(set, caught[k]);
}

static void hold_signals(int how, sigset_t *old)
{
    sigset_t set;
    caught_set(&set);
    (void)sigprocmask(how, &set, old);
}

static int arm(const char *tmp)
{
    size_t len = strlen(tmp);
    if (len >= sizeof pending) {
        errno = ENAMETOOLONG;
        return -1;
    }
    memcpy(pending, tmp, len + 1);
    armed = 1;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sa.sa_flags = (int)SA_RESETHAND; /* 0x80000000 on Linux */
    caught_set(&sa.sa_mask); /* one handler at a time */
    for (int k = 0; k < CAUGHT; k++) {
        /* a signal ignored from the start (nohup, a background job of a script) stays ignored */
        (void)sigaction(caught[k], NULL, &previous[k]);
        if (previous[k].sa_handler != SIG_IGN)
            (void)sigaction(caught[k], &sa, NULL);
    }
    return 0;
}

static void disarm(void)
{
    for (int k = 0; k < CAUGHT; k++)
        (void)sigaction(caught[k], &previous[k], NULL);
    armed = 0;
}

void out_hold(out_file *o)
{
    if (o->f != NULL)
        (void)fclose(o->f); /* empty: nothing to lose */
    o->f = NULL;
    hold_signals(SIG_BLOCK, NULL);
}

void out_release(void)
{
    int e = errno; /* the writer's */
    hold_signals(SIG_UNBLOCK, NULL);
    errno = e;
}

/* ---- the files ---- */

static void forget(out_file *o)
{
    free(o->tmp);
    free(o->target);
    o->tmp = NULL;
    o->target = NULL;
}

/* o->target: path, or the file a symbolic link at path finally names. 0, or -1 with errno. */
static int resolve(out_file *o)
{
    struct stat link;
    if (lstat(o->path, &link) != 0 || !S_ISLNK(link.st_mode)) {
        o->target = strdup(o->path);
        return o->target != NULL ? 0 : -1;
    }
    o->target = realpath(o->path, NULL);
    if (o->target == NULL && errno == ENOENT)
        o->why = "a symbolic link to a missing file (not written through, as by cp)";
    return o->target != NULL ? 0 : -1;
}

/* Create "<directory of the target>/.bezsurf-XXXXXX" with the permissions fopen would give (the
 * old file's, or 0666 less the umask) and arm the removal on a signal. 0, or -1 with errno. */
static int make_tmp(out_file *o, const struct stat *old, int exists)
{
    const char *slash = strrchr(o->target, '/');
    size_t dir_len = slash ? (size_t)(slash - o->target) + 1 : 0;
    static const char name[] = ".bezsurf-XXXXXX";
    o->tmp = malloc(dir_len + sizeof name);
    if (o->tmp == NULL)
        return -1;
    memcpy(o->tmp, o->target, dir_len);
    memcpy(o->tmp + dir_len, name, sizeof name);
    sigset_t mask;
    hold_signals(SIG_BLOCK, &mask); /* from its creation on, a signal finds its name */
    int fd = mkstemp(o->tmp);
    if (fd >= 0) {
        mode_t mode = old->st_mode & 07777;
        if (!exists) {
            mode_t umask_was = umask(0);
            umask(umask_was);
            mode = 0666 & ~umask_was;
        }
        (void)fchmod(fd, mode);
        o->f = arm(o->tmp) == 0 ? fdopen(fd, "wb") : NULL;
    }
    int e = errno;
    if (fd >= 0 && o->f == NULL) {
        close(fd);
        unlink(o->tmp);
        if (armed)
            disarm();
    }
    (void)sigprocmask(SIG_SETMASK, &mask, NULL);
    errno = e;
    return o->f != NULL ? 0 : -1;
}

int out_open(const char *path, out_file *o)
{
    o->f = NULL;
    o->tmp = NULL;
    o->target = NULL;
    o->path = path;
    o->why = NULL;
    if (path[0] == '\0') {
        o->why = "the file name is empty";
        errno = ENOENT;
        return -1;
    }
    struct stat old;
    memset(&old, 0, sizeof old);
    int rc = resolve(o), exists = rc == 0 && stat(o->target, &old) == 0;
    if (exists && !S_ISREG(old.st_mode)) {
        errno = S_ISDIR(old.st_mode) ? EISDIR : EINVAL;
        rc = -1;
    }
    /* a file the user may not write is not replaced behind its back (rename would) */
    if (rc == 0 && exists && access(o->target, W_OK) != 0)
        rc = -1;
    if (rc == 0)
        rc = make_tmp(o, &old, exists);
    if (rc != 0) {
        int e = errno;
        forget(o);
        errno = e;
    }
    return rc;
}

/* Make the rename durable: sync the target's directory (best effort: some file systems refuse, and
 * the data is safe already; a crash could lose only the new name). */
static void sync_dir_of(char *target)
{
    char *slash = strrchr(target, '/');
    if (slash != NULL)
        *slash = '\0';
    int fd = open(slash == target ? "/" : slash != NULL ? target : ".", O_RDONLY);
    if (fd >= 0) {
        (void)fsync(fd);
        (void)close(fd);
    }
}

/* Flush, sync and close f: 0, or the errno of the first step that failed (f is closed anyway). */
static int settle(FILE *f)
{
    int e = 0;
    if (fflush(f) != 0 || ferror(f))
        e = errno ? errno : EIO;
    else if (fsync(fileno(f)) != 0 && errno != EINVAL) /* EINVAL: a file that cannot be synced */
        e = errno;
    if (fclose(f) != 0 && e == 0)
        e = errno;
    return e;
}

int out_close(out_file *o, int ok)
{
    if (o->tmp == NULL)
        return ok ? 0 : -1;
    int e = ok ? 0 : (errno ? errno : EIO);
    if (o->f != NULL && ok)
        e = settle(o->f); /* the data on disk before the name points at it */
    else if (o->f != NULL)
        (void)fclose(o->f);
    o->f = NULL;
    if (e == 0 && rename(o->tmp, o->target) != 0)
        e = errno;
    if (e != 0)
        (void)unlink(o->tmp);
    else
        sync_dir_of(o->target);
    disarm();
    forget(o);
    errno = e;
    return e == 0 ? 0 : -1;
}
