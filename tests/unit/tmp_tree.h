/* tmp_tree.h - making and removing a test's temporary folder tree, shared
 * by the unit tests that write files. */
#ifndef GLINT_TESTS_TMP_TREE_H
#define GLINT_TESTS_TMP_TREE_H

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Removes path and, for a folder, everything in it; folders a test made
 * unreadable are made readable first. Missing paths are fine. */
static inline void remove_tree(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return;
    if (!S_ISDIR(st.st_mode)) {
        unlink(path);
        return;
    }
    chmod(path, 0700);
    DIR *d = opendir(path);
    if (d) {
        struct dirent *e;
        char child[4096 + 256 + 2]; /* a path, a slash and a name */
        while ((e = readdir(d)) != NULL) {
            if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
                continue;
            if (snprintf(child, sizeof child, "%s/%s", path, e->d_name) < (int)sizeof child)
                remove_tree(child);
        }
        closedir(d);
    }
    rmdir(path);
}

/* Makes dir (size bytes) a new, empty folder GLINT_TEST_TMP/NAME-PID, or
 * under /tmp without GLINT_TEST_TMP; 0, or -1 when it cannot. */
static inline int make_tmp_tree(char *dir, size_t size, const char *name)
{
    const char *base = getenv("GLINT_TEST_TMP");
    if (!base || !*base)
        base = "/tmp";
    snprintf(dir, size, "%s/%s-%ld", base, name, (long)getpid());
    remove_tree(dir);
    return mkdir(dir, 0755) == 0 ? 0 : -1;
}

#endif
