/* jpeg_read.c - decoding JPEG files for image textures with libjpeg
 * (libjpeg-turbo), into 8-bit sRGB RGB. A damaged file is an error, never
 * a picture with invented pixels, a line on stderr or an exit, and the size
 * in the header is checked before any pixel memory is allocated. */
#include <setjmp.h>
#include <stdio.h>
#include <jpeglib.h>
#include <jerror.h>
#include "core/error.h"
#include "image/image_reader.h"

/* Each scan of a progressive JPEG is another pass over the whole image, and
 * a hostile file can hold thousands; libjpeg-turbo advises capping them. */
#define MAX_JPEG_SCANS 1000

/* libjpeg reports errors through these callbacks; the struct starts with its
 * error manager so the manager's address is the struct's. */
typedef struct jpeg_failure {
    struct jpeg_error_mgr mgr;
    jmp_buf jump;
    char reason[JMSG_LENGTH_MAX];
} jpeg_failure;

static void jpeg_fail(j_common_ptr cinfo)
{
    jpeg_failure *fail = (jpeg_failure *)cinfo->err;
    cinfo->err->format_message(cinfo, fail->reason);
    longjmp(fail->jump, 1);
}

/* On damaged data libjpeg only warns and invents the missing pixels; a
 * texture that silently turns grey is worse than an error, so only warnings
 * about metadata are let through. Trace messages (level >= 0) are dropped. */
static void jpeg_emit(j_common_ptr cinfo, int level)
{
    int code = cinfo->err->msg_code;
    if (level < 0 && code != JWRN_JFIF_MAJOR && code != JWRN_ADOBE_XFORM && code != JWRN_BOGUS_ICC
        && code != JWRN_EXTRANEOUS_DATA)
        jpeg_fail(cinfo);
}

static void jpeg_output_nothing(j_common_ptr cinfo)
{
    (void)cinfo;
}

static void jpeg_limit_scans(j_common_ptr cinfo)
{
    if (((j_decompress_ptr)cinfo)->input_scan_number > MAX_JPEG_SCANS) {
        jpeg_failure *fail = (jpeg_failure *)cinfo->err;
        snprintf(fail->reason, sizeof fail->reason, "more than %d progressive scans",
                 MAX_JPEG_SCANS);
        longjmp(fail->jump, 1);
    }
}

static glint_status decode_jpeg(texture_image *out, const void *data, size_t size, const char *what,
                                glint_error *err)
{
    struct jpeg_decompress_struct cinfo;
    struct jpeg_progress_mgr progress = {.progress_monitor = jpeg_limit_scans};
    jpeg_failure fail;
    glint_status st;

    cinfo.err = jpeg_std_error(&fail.mgr);
    fail.mgr.error_exit = jpeg_fail;
    fail.mgr.emit_message = jpeg_emit;
    fail.mgr.output_message = jpeg_output_nothing;
    if (setjmp(fail.jump)) {
        jpeg_destroy_decompress(&cinfo);
        texture_image_free(out);
        return image_read_corrupt(what, fail.reason, err);
    }
    jpeg_create_decompress(&cinfo);
    cinfo.progress = &progress;
    jpeg_mem_src(&cinfo, data, (unsigned long)size);
    jpeg_read_header(&cinfo, TRUE);
    if (cinfo.jpeg_color_space == JCS_CMYK || cinfo.jpeg_color_space == JCS_YCCK)
        st = error_set(err, GLINT_ERR_INVALID,
                       "texture '%s' is a CMYK JPEG, which is not supported (save it as RGB)",
                       what);
    else
        st = image_read_alloc(out, cinfo.image_width, cinfo.image_height, 3, true, what, err);
    if (st != GLINT_OK) {
        jpeg_destroy_decompress(&cinfo);
        return st;
    }
    cinfo.out_color_space = JCS_RGB;
    jpeg_start_decompress(&cinfo);
    size_t row_bytes = (size_t)cinfo.output_width * 3;
    while (cinfo.output_scanline < cinfo.output_height) {
        JSAMPROW row = out->owned + row_bytes * cinfo.output_scanline;
        jpeg_read_scanlines(&cinfo, &row, 1);
    }
    jpeg_finish_decompress(&cinfo);
    jpeg_destroy_decompress(&cinfo);
    return GLINT_OK;
}

static const unsigned char jpeg_signature[3] = {0xff, 0xd8, 0xff};

const image_reader jpeg_reader = {"JPEG", jpeg_signature, sizeof jpeg_signature, decode_jpeg};
