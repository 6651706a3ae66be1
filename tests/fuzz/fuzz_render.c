/* fuzz_render.c - libFuzzer target for rendering what the scene readers
 * accept: the input's first byte picks the reader (odd: a YAML scene,
 * "fuzz.yaml"; even: NFF, "fuzz.nff"), the rest is the file. A scene that
 * loads is rendered small on one thread, so the sanitizers watch the
 * shapes' tests, the accelerator and the shading on every value the
 * readers let through (huge, tiny, degenerate). A render must succeed, or
 * fail with a message, and leave no NaN in the image; rendered again in
 * tiles of 4 pixels, it must give the same bits (the image never depends on
 * the tile size). Not yet on two threads: Embree's BVH, built on two, can
 * order the same primitives differently from run to run, and a scene of
 * coincident see-through shapes then differs in its last bits
 * (tests/fuzz/README.md). A scene may be slow
 * to render and still right (hundreds of lights, thousands of samples a
 * material): a render still going after a second is cancelled, which
 * libFuzzer would otherwise report as a hang. */
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "glint.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The render's cancel flag, set by the watch a second after it started
 * unless the render ended first. */
static volatile int cancel;
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t ended_signal = PTHREAD_COND_INITIALIZER;
static int ended;

static void *watch(void *arg)
{
    (void)arg;
    struct timespec until;
    clock_gettime(CLOCK_REALTIME, &until);
    until.tv_sec += 1;
    pthread_mutex_lock(&lock);
    int waited = 0;
    while (!ended && waited != ETIMEDOUT)
        waited = pthread_cond_timedwait(&ended_signal, &lock, &until);
    if (!ended)
        cancel = 1;
    pthread_mutex_unlock(&lock);
    return NULL;
}

/* glint_render with options o, cancelled if still going after a second;
 * an error must come with a message. */
static glint_status render_watched(const glint_scene *scene, glint_render_options *o, glint_image *out)
{
    glint_error err;
    err.message[0] = '\0';
    o->cancel = &cancel;
    cancel = 0;
    ended = 0;
    pthread_t watcher;
    bool watched = pthread_create(&watcher, NULL, watch, NULL) == 0;
    glint_status st = glint_render(scene, o, out, NULL, &err);
    pthread_mutex_lock(&lock);
    ended = 1;
    pthread_cond_signal(&ended_signal);
    pthread_mutex_unlock(&lock);
    if (watched)
        pthread_join(watcher, NULL);
    if (st != GLINT_OK && err.message[0] == '\0')
        abort();
    return st;
}

/* At most `most`: what the render of one input may cost is bounded. */
static int at_most(int v, int most)
{
    return v < most ? v : most;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    const char *name = data[0] & 1 ? "fuzz.yaml" : "fuzz.nff";
    glint_error err;
    err.message[0] = '\0';
    glint_scene *scene = glint_scene_load_memory((const char *)data + 1, size - 1, name, NULL, &err);
    if (!scene)
        return 0;
    glint_settings s = glint_scene_get_settings(scene);
    s.width = at_most(s.width, 6);
    s.height = at_most(s.height, 6);
    s.samples_per_pixel = 1;
    s.adaptive_max_samples = 0;
    s.max_depth = at_most(s.max_depth, 3);
    s.occlusion_samples = at_most(s.occlusion_samples, 4);
    s.emission_samples = at_most(s.emission_samples, 4);
    s.light_samples = at_most(s.light_samples, 4);
    s.dispersion_bands = at_most(s.dispersion_bands, 4);
    glint_image first = {0}, again = {0};
    if (glint_scene_set_settings(scene, &s, &err) == GLINT_OK &&
        render_watched(scene, &(glint_render_options){.threads = 1}, &first) == GLINT_OK) {
        for (size_t i = 0; i < 3 * (size_t)first.width * (size_t)first.height; i++)
            if (isnan(first.pixels[i]))
                abort();
        if (render_watched(scene, &(glint_render_options){.threads = 1, .tile_size = 4}, &again) == GLINT_OK &&
            memcmp(first.pixels, again.pixels, 3 * sizeof(float) * (size_t)first.width * (size_t)first.height) != 0)
            abort();
    }
    glint_image_free(&first);
    glint_image_free(&again);
    glint_scene_free(scene);
    return 0;
}
