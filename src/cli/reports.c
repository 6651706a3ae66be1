/* reports.c - what the glint and glint-mpi commands report on stdout
 * (--check, --print-scene) and the exit code of a run whose report may
 * not have been written whole (reports.h). */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "cli/frames.h"
#include "cli/report_flush.h"
#include "cli/reports.h"
#include "cli/setup.h"

int cli_reported(int code)
{
    cli_flush_report();
    bool out_lost = cli_report_errno() != 0 || ferror(stdout);
    bool err_lost = fflush(stderr) != 0 || ferror(stderr);
    if (!out_lost && !err_lost)
        return code;
    /* A write that failed inside printf left its reason behind. */
    if (out_lost && code < CLI_EXIT_IO)
        cli_complain(CLI_EXIT_IO, "cannot write '<stdout>': %s", strerror(cli_report_errno() ? cli_report_errno() : EIO));
    return code > CLI_EXIT_IO ? code : CLI_EXIT_IO;
}

/* Prints `before`, then n and the word for n things: "1 texture", "2 textures". */
static void print_count(const char *before, long long n, const char *one, const char *many)
{
    printf("%s%lld %s", before, n, n == 1 ? one : many);
}

/* Checks one scene file: what it holds on stdout, or its problems on stderr. */
static int check_one(const cli_options *o, const char *path)
{
    int code;
    glint_scene *scene = cli_load_scene(o, path, 0, "not valid", true, &code);
    if (!scene)
        return code;
    glint_scene_counts c = glint_scene_get_counts(scene);
    printf("%s: ok:", cli_scene_name(path));
    print_count(" ", c.textures, "texture", "textures");
    print_count(", ", c.materials, "material", "materials");
    print_count(", ", c.shapes, "shape", "shapes");
    if (c.sphere_sets > 0) {
        print_count(" (", c.sphere_sets, "sphere set", "sphere sets");
        print_count(" of ", c.set_spheres, "sphere", "spheres");
        putchar(')');
    }
    print_count(", ", c.lights, "light", "lights");
    if (c.meshes > 0) {
        print_count(", ", c.meshes, "mesh", "meshes");
        print_count(" (", c.triangles, "triangle", "triangles");
        if (c.instances == 1)
            fputs(") placed once", stdout);
        else
            printf(") placed %d times", c.instances);
    }
    putchar('\n');
    glint_scene_free(scene);
    return CLI_EXIT_OK;
}

int cli_check_only(const cli_options *o)
{
    int worst = CLI_EXIT_OK;
    for (int i = 0; i < o->scene_count; i++) {
        int code = check_one(o, o->scenes[i]);
        if (code > worst)
            worst = code;
        /* In order with the problems on stderr, when both go to one place. */
        cli_flush_report();
    }
    return worst;
}

/* The scene, with the output `output` names (when not NULL), as a scene
 * file on stdout; frees the scene. The exit code. */
static int print_scene(glint_scene *scene, const char *output)
{
    glint_error err = {0};
    glint_status st = output ? glint_scene_set_output(scene, output, &err) : GLINT_OK;
    if (!st)
        st = glint_scene_write_yaml(scene, stdout, &err);
    glint_scene_free(scene);
    return st ? cli_complain(cli_exit_code_of(st), "%s", err.message) : CLI_EXIT_OK;
}

int cli_print_frame(const cli_options *o)
{
    cli_run r;
    int code = cli_prepare(o, true, 0, &r);
    if (code >= 0)
        return code;
    cli_frames f;
    if ((code = cli_frames_choose(o, &r.settings, r.dest.path, &f)) >= 0) {
        glint_scene_free(r.scene);
        return code;
    }
    double time = cli_frame_time(&f, f.first);
    if (time != 0) {
        glint_scene_free(r.scene);
        if ((code = cli_prepare(o, true, time, &r)) >= 0)
            return code;
    }
    /* Every keyed value fixed at the frame's time: a still, whose seed is
     * the frame's, so that it renders the frame's bytes. */
    r.settings.seed = glint_settings_random_seed(&(glint_settings){.seed = r.settings.seed, .frame = f.first});
    r.settings.frame_start = r.settings.frame_end = 0;
    glint_error err = {0};
    if (glint_scene_set_settings(r.scene, &r.settings, &err)) {
        glint_scene_free(r.scene);
        return cli_complain(CLI_EXIT_INTERNAL, "%s", err.message);
    }
    return print_scene(r.scene, o->output);
}

