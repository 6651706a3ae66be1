/* scene_readers.c - the list of scene-file readers, one line each, and
 * the public loading calls, which pick a reader by the file's name. */
#include <string.h>
#include <strings.h>
#include "scenefile/scene_reader.h"

static const scene_reader *const READERS[] = {&yaml_scene_reader, &nff_scene_reader};

const scene_reader *scene_reader_for(const char *name)
{
    const char *dot = name ? strrchr(name, '.') : NULL;
    for (size_t i = 0; dot && i < sizeof READERS / sizeof READERS[0]; i++)
        for (const char *const *ext = READERS[i]->extensions; *ext; ext++)
            if (strcasecmp(dot, *ext) == 0)
                return READERS[i];
    return &yaml_scene_reader;
}

glint_scene *glint_scene_load_file(const char *path, const glint_load_options *options, glint_error *err)
{
    return scene_reader_for(path)->load_file(path, options, err);
}

glint_scene *glint_scene_load_memory(const char *data, size_t size, const char *name,
                                     const glint_load_options *options, glint_error *err)
{
    return scene_reader_for(name)->load_memory(data, size, name, options, err);
}

glint_scene *glint_scene_load_stream(FILE *in, const char *name, const glint_load_options *options,
                                     glint_error *err)
{
    return scene_reader_for(name)->load_stream(in, name, options, err);
}
