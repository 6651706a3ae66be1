/* scene_file.h - how the YAML loader (scene_file.c) reads each file's
 * objects: while the file is parsed, or from its whole tree (users get the
 * default; tests and the fuzzer set the others to compare the ways); and
 * the most it reads of one file. */
#ifndef GLINT_SCENEFILE_SCENE_FILE_H
#define GLINT_SCENEFILE_SCENE_FILE_H

typedef enum scene_file_mode {
    SCENE_FILE_STREAMED,       /* while the file is parsed, and, when that
                                  attempt gives up, again from whole trees:
                                  the default; either way a load makes the
                                  same calls and the same reports */
    SCENE_FILE_WHOLE,          /* from whole trees only */
    SCENE_FILE_STREAMED_ONLY,  /* the attempt alone: a load it gives up is
                                  refused, reporting nothing, with err its
                                  first problem */
} scene_file_mode;

/* The largest scene file, include or standard input a load reads: 64 MiB. */
#define SCENE_FILE_MAX_BYTES (64L << 20)

/* Sets the mode of every load after it; not while another thread loads. */
void scene_file_set_mode(scene_file_mode mode);

#endif
