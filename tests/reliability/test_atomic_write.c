/* Files written by the library replace their target atomically: a write that fails half-way (here
 * a file-size limit, RLIMIT_FSIZE) leaves the old file as it was and no temporary file behind,
 * and says why through errno; a directory, FIFO or device is never replaced, and reading one is
 * refused at once (a FIFO without a writer never blocks). Also: the largest .bpt file read,
 * 256 MiB, is read, one byte more is refused. */
#define _POSIX_C_SOURCE 200809L

#include "harness.h"

#include <bezsurf.h>

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

static char dir[] = "atomic_XXXXXX";
static char path[256];

static const char *in_dir(const char *name)
{
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return path;
}

static void put_file(const char *name, const char *text)
{
    FILE *f = fopen(in_dir(name), "wb");
    CHECK(f != NULL);
    if (f != NULL) {
        fputs(text, f);
        fclose(f);
    }
}

static int same_text(const char *name, const char *text)
{
    char buf[256];
    FILE *f = fopen(in_dir(name), "rb");
    if (f == NULL)
        return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    return strcmp(buf, text) == 0;
}

/* Number of entries in the directory other than . and .. */
static int entries(void)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d != NULL && (e = readdir(d)) != NULL;)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    if (d != NULL)
        closedir(d);
    return n;
}

static void limit_file_size(rlim_t bytes)
{
    struct rlimit r;
    CHECK(getrlimit(RLIMIT_FSIZE, &r) == 0);
    r.rlim_cur = bytes == RLIM_INFINITY ? r.rlim_max : bytes;
    CHECK(setrlimit(RLIMIT_FSIZE, &r) == 0);
}

static const char old_text[] = "the previous content\n";

static void test_failed_writes(const bs_surface *teapot, const bs_mesh *m)
{
    static const int formats[4] = {BS_MESH_OBJ, BS_MESH_PLY, BS_MESH_PLY_ASCII, BS_MESH_STL};
    put_file("old.bpt", old_text);
    put_file("old.mesh", old_text);
    int before = entries();
    limit_file_size(4096); /* the teapot's text and its meshes are larger */
    errno = 0;
    CHECK_STATUS(bs_surface_write_bpt_file(teapot, in_dir("old.bpt")), BS_ERR_IO);
    CHECKF(errno == EFBIG, ".bpt: errno %d, expected EFBIG", errno);
    errno = 0;
    CHECK_STATUS(bs_surface_write_obj_file(teapot, in_dir("old.bpt")), BS_ERR_IO);
    CHECKF(errno == EFBIG, "OBJ: errno %d, expected EFBIG", errno);
    for (int k = 0; k < 4; k++) {
        errno = 0;
        CHECK_STATUS(bs_mesh_write(m, formats[k], in_dir("old.mesh")), BS_ERR_IO);
        CHECKF(errno == EFBIG, "mesh format %d: errno %d, expected EFBIG", formats[k], errno);
    }
    CHECK_STATUS(bs_surface_write_bpt_file(teapot, in_dir("new.bpt")), BS_ERR_IO);
    limit_file_size(RLIM_INFINITY);
    CHECKF(same_text("old.bpt", old_text), "a failed .bpt write changed the old file");
    CHECKF(same_text("old.mesh", old_text), "a failed mesh write changed the old file");
    CHECKF(entries() == before, "a failed write left %d files behind", entries() - before);
}

static void test_replaced_whole(const bs_surface *teapot, const bs_mesh *m)
{
    put_file("keep.bpt", old_text);
    CHECK(chmod(in_dir("keep.bpt"), 0640) == 0);
    int before = entries();
    CHECK_STATUS(bs_surface_write_bpt_file(teapot, in_dir("keep.bpt")), BS_OK);
    bs_surface *back = NULL;
    CHECK_STATUS(bs_surface_read_bpt_file(in_dir("keep.bpt"), NULL, &back), BS_OK);
    CHECK(bs_surface_count(back) == 32);
    bs_surface_destroy(back);
    struct stat st;
    CHECK(stat(in_dir("keep.bpt"), &st) == 0 && (st.st_mode & 0777) == 0640);
    CHECK_STATUS(bs_surface_write_obj_file(teapot, in_dir("keep.bpt")), BS_OK);
    CHECK_STATUS(bs_surface_read_obj_file(in_dir("keep.bpt"), NULL, &back), BS_OK);
    CHECK(bs_surface_count(back) == 32);
    bs_surface_destroy(back);
    CHECK(stat(in_dir("keep.bpt"), &st) == 0 && (st.st_mode & 0777) == 0640);
    CHECK_STATUS(bs_mesh_write(m, BS_MESH_STL, in_dir("keep.bpt")), BS_OK);
    CHECK(stat(in_dir("keep.bpt"), &st) == 0 && (size_t)st.st_size == 84 + 50 * bs_mesh_triangle_count(m));
    CHECKF(entries() == before, "a write left %d files behind", entries() - before);
}

static void test_not_regular(const bs_surface *teapot, const bs_mesh *m)
{
    bs_surface *s = (bs_surface *)(void *)&path;
    bs_parse_error err;
    CHECK(mkdir(in_dir("sub"), 0755) == 0);
    CHECK_STATUS(bs_surface_write_bpt_file(teapot, in_dir("sub")), BS_ERR_IO);
    CHECK_STATUS(bs_mesh_write(m, BS_MESH_OBJ, in_dir("sub")), BS_ERR_IO);
    CHECK_STATUS(bs_surface_write_obj_file(teapot, in_dir("sub")), BS_ERR_IO);
    struct stat st;
    CHECK(stat(in_dir("sub"), &st) == 0 && S_ISDIR(st.st_mode));
    CHECK_STATUS(bs_surface_read_bpt_file(in_dir("sub"), &err, &s), BS_ERR_IO);
    CHECK(s == NULL && strstr(err.message, "not a regular file") != NULL);
    /* A FIFO with nobody at the other end: opening it plainly would block for ever. */
    CHECK(mkfifo(in_dir("fifo"), 0644) == 0);
    alarm(20);
    s = (bs_surface *)(void *)&path;
    CHECK_STATUS(bs_surface_read_bpt_file(in_dir("fifo"), &err, &s), BS_ERR_IO);
    CHECK(s == NULL && strstr(err.message, "not a regular file") != NULL);
    CHECK_STATUS(bs_surface_read_obj_file(in_dir("fifo"), &err, &s), BS_ERR_IO);
    CHECK_STATUS(bs_surface_read_iges_file(in_dir("fifo"), &err, &s), BS_ERR_IO);
    CHECK(s == NULL && strstr(err.message, "not a regular file") != NULL);
    CHECK_STATUS(bs_surface_write_obj_file(teapot, in_dir("fifo")), BS_ERR_IO);
    CHECK_STATUS(bs_surface_write_bpt_file(teapot, in_dir("fifo")), BS_ERR_IO);
    CHECK_STATUS(bs_mesh_write(m, BS_MESH_PLY, in_dir("fifo")), BS_ERR_IO);
    alarm(0);
    CHECK(stat(in_dir("fifo"), &st) == 0 && S_ISFIFO(st.st_mode));
    unlink(in_dir("fifo"));
    rmdir(in_dir("sub"));
}

/* Files of 256 MiB (sparse, all NUL bytes: a parse error at the first byte) and one byte more. */
static void test_size_limit(void)
{
    bs_surface *s = NULL;
    bs_parse_error err;
    const off_t max = (off_t)256 << 20;
    for (int extra = 0; extra <= 1; extra++) {
        int fd = open(in_dir("big.bpt"), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        CHECK(fd >= 0 && ftruncate(fd, max + extra) == 0);
        if (fd >= 0)
            close(fd);
        bs_status st = bs_surface_read_bpt_file(in_dir("big.bpt"), &err, &s);
        if (extra == 0)
            CHECKF(st == BS_ERR_PARSE, "a file of exactly 256 MiB: status %d, expected BS_ERR_PARSE", st);
        else
            CHECKF(st == BS_ERR_IO && strstr(err.message, "256 MiB") != NULL,
                   "a file of 256 MiB + 1: status %d, expected BS_ERR_IO", st);
    }
    unlink(in_dir("big.bpt"));
}

int main(void)
{
    signal(SIGXFSZ, SIG_IGN); /* a write past RLIMIT_FSIZE then fails with EFBIG */
    if (mkdtemp(dir) == NULL) {
        perror("mkdtemp");
        return 1;
    }
    bs_surface *teapot = NULL;
    bs_mesh *m = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &teapot), BS_OK);
    CHECK_STATUS(bs_surface_tessellate_uniform(teapot, 4, 4, 0, &m), BS_OK);
    if (teapot != NULL && m != NULL) {
        test_failed_writes(teapot, m);
        test_replaced_whole(teapot, m);
        test_not_regular(teapot, m);
        test_size_limit();
    }
    bs_mesh_destroy(m);
    bs_surface_destroy(teapot);
    const char *names[] = {"old.bpt", "old.mesh", "keep.bpt", "new.bpt"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        unlink(in_dir(names[k]));
    rmdir(dir);
    return bs_test_exit("test_atomic_write");
}
