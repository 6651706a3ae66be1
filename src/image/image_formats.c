/* image_formats.c - the registry of the image formats glint writes, one
 * line a format (each defined in a file of its own), and the look-ups that
 * glint_image_write, its path check, the scene file's `output` key and the
 * command line go through. Messages and `glint --help` list the formats in
 * this order. */
#include <string.h>
#include <strings.h>
#include "core/word_list.h"
#include "image/image_format.h"

extern const image_writer png_writer, ppm_writer, exr_writer;

static const image_writer *const writers[] = {
    &png_writer, /* png_write.c */
    &ppm_writer, /* ppm_write.c */
    &exr_writer, /* exr_write.c */
};

#define WRITER_COUNT ((int)(sizeof writers / sizeof writers[0]))

const image_writer *image_writer_for_path(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    for (int i = 0; dot && i < WRITER_COUNT; i++)
        for (const char *const *ext = writers[i]->format.extensions; *ext; ext++)
            if (strcasecmp(dot, *ext) == 0)
                return writers[i];
    return NULL;
}

const image_writer *image_writer_for_format(const glint_image_format *format)
{
    for (int i = 0; i < WRITER_COUNT; i++)
        if (&writers[i]->format == format)
            return writers[i];
    return NULL;
}

const char *image_writer_extensions(char *buf, size_t size)
{
    int count = 0, index = 0;
    for (int i = 0; i < WRITER_COUNT; i++)
        for (const char *const *ext = writers[i]->format.extensions; *ext; ext++)
            count++;
    buf[0] = '\0';
    for (int i = 0; i < WRITER_COUNT; i++)
        for (const char *const *ext = writers[i]->format.extensions; *ext; ext++)
            word_list_append(buf, size, *ext, index++, count);
    return buf;
}

const glint_image_format *glint_image_format_at(int index)
{
    return index >= 0 && index < WRITER_COUNT ? &writers[index]->format : NULL;
}

const glint_image_format *glint_image_format_for_path(const char *path)
{
    const image_writer *writer = path ? image_writer_for_path(path) : NULL;
    return writer ? &writer->format : NULL;
}

const glint_image_format *glint_image_format_named(const char *name)
{
    for (int i = 0; name && i < WRITER_COUNT; i++) {
        if (strcasecmp(name, writers[i]->format.name) == 0)
            return &writers[i]->format;
        for (const char *const *ext = writers[i]->format.extensions; *ext; ext++)
            if (strcasecmp(name, *ext + 1) == 0)
                return &writers[i]->format;
    }
    return NULL;
}
