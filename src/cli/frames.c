/* frames.c - which frames a run renders, their file names, and whether a
 * frame's file is already done (frames.h). */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include "cli/frames.h"

int cli_frames_choose(const cli_options *o, const glint_settings *s, const char *output, cli_frames *f)
{
    f->first = o->frame_first >= 0 ? (int)o->frame_first : s->frame_start;
    f->last = o->frame_first >= 0 ? (int)o->frame_last : s->frame_end;
    f->fps = s->fps;
    /* --print-scene prints the first frame alone. */
    if (f->last == f->first || o->print_scene)
        return -1;
    if (o->scene && strcmp(o->scene, "-") == 0)
        return cli_complain(CLI_EXIT_USAGE, "frames %d to %d need the scene in a file: standard input is read once",
                            f->first, f->last);
    if (strcmp(output, "-") == 0)
        return cli_complain(CLI_EXIT_USAGE, "frames %d to %d go to files, not standard output: give -o NAME-####.png",
                            f->first, f->last);
    if (!strchr(output, '#'))
        return cli_complain(CLI_EXIT_USAGE, "frames %d to %d need an output name with #s for the frame's number, "
                                            "such as -o frame-####.png; got '%s'", f->first, f->last, output);
    return -1;
}

double cli_frame_time(const cli_frames *f, int frame)
{
    return frame / f->fps;
}

bool cli_frame_path(const char *pattern, int frame, char *out, size_t size)
{
    const char *end = strrchr(pattern, '#');
    if (!end)
        return snprintf(out, size, "%s", pattern) < (int)size;
    const char *start = end;
    while (start > pattern && start[-1] == '#')
        start--;
    int n = snprintf(out, size, "%.*s%0*d%s", (int)(start - pattern), pattern, (int)(end - start + 1), frame, end + 1);
    return n >= 0 && n < (int)size;
}

/* A binary PPM's header (P6, width, height, maxval, one white space) and
 * whether the file holds exactly its pixels after it. */
static bool ppm_whole(FILE *f, long size)
{
    int width, height, max, end;
    if (fscanf(f, "P6 %d %d %d%n", &width, &height, &max, &end) != 3 || width <= 0 || height <= 0 || max <= 0 ||
        max > 65535)
        return false;
    long bytes = (long)width * height * 3 * (max > 255 ? 2 : 1);
    return size == end + 1 + bytes;
}

bool cli_frame_done(const char *path)
{
    struct stat st;
    if (stat(path, &st) || !S_ISREG(st.st_mode))
        return false;
    FILE *f = fopen(path, "rb");
    if (!f)
        return false;
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    static const unsigned char exr[4] = {0x76, 0x2f, 0x31, 0x01};
    unsigned char head[8] = {0}, tail[12] = {0};
    long size = (long)st.st_size;
    bool done = false;
    if (size >= 8 && fread(head, 1, 8, f) == 8) {
        if (memcmp(head, png, 8) == 0)
            done = size >= 20 && fseek(f, -12, SEEK_END) == 0 && fread(tail, 1, 12, f) == 12 &&
                   memcmp(tail, iend, 12) == 0;
        else if (memcmp(head, exr, 4) == 0)
            done = true;
        else if (head[0] == 'P' && head[1] == '6')
            done = fseek(f, 0, SEEK_SET) == 0 && ppm_whole(f, size);
    }
    fclose(f);
    return done;
}
