/* display.c - the --display window (display.h). The render threads copy
 * each finished tile into the display's own float copy of the image and
 * queue its rectangle; the window's thread, the only one calling SDL, takes
 * the queue at most 30 times a second, encodes those rectangles to sRGB
 * bytes in a streaming texture and presents it, scaled to the window. The
 * float copy is what s saves: the finished tiles, black elsewhere, as
 * --partial writes them. */
#include <SDL.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli/display.h"
#include "image/srgb.h"

/* The shortest time between two frames of new tiles: 30 a second. */
#define FRAME_MS 33
/* The placeholder: a checkerboard of squares this wide, in two dim greys. */
#define CHECKER 16
static const unsigned char CHECKER_GREYS[2] = {0x1c, 0x2c};

typedef struct tile_rect {
    int x0, y0, x1, y1;
} tile_rect;

/* STARTING until the window's thread has opened the window (SHOWING) or
 * failed to (FAILED); GONE once it has left its loop, after which no SDL
 * event may be pushed to it. */
enum display_state { STARTING, SHOWING, FAILED, GONE };

struct display {
    int width, height;
    char title[128];                  /* "glint - NAME", ASCII */
    char *save_path;
    glint_image_write_options write_options;
    volatile sig_atomic_t *cancel;
    pthread_t thread;
    Uint32 wake_event;                /* an SDL event type of ours, to wake the window's thread */

    pthread_mutex_t lock;
    pthread_cond_t started;           /* the state left STARTING */
    /* Under the lock: */
    enum display_state state;
    char why[256];                    /* why the window did not open */
    float *pixels;                    /* the finished tiles, black elsewhere */
    tile_rect *fresh;                 /* tiles copied in since the window last took them */
    size_t fresh_count, rect_capacity;
    long long pixels_done;
    bool finished, stop;
    double seconds;

    /* The window's thread alone: */
    tile_rect *taken;                 /* swapped with fresh: the tiles to show at this frame */
    SDL_Window *window;
    SDL_Renderer *renderer;
    SDL_Texture *texture;
    unsigned char *rows;              /* sRGB bytes of a rectangle on its way to the texture */
};

/* Records why the window did not open; false. */
static bool failed(display *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static bool failed(display *d, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(d->why, sizeof d->why, fmt, ap);
    va_end(ap);
    return false;
}

/* Fills the texture with the placeholder, CHECKER rows at a time. */
static void show_placeholder(display *d)
{
    int pitch = 3 * d->width;
    for (int y0 = 0; y0 < d->height; y0 += CHECKER) {
        int rows = d->height - y0 < CHECKER ? d->height - y0 : CHECKER;
        for (int y = 0; y < rows; y++)
            for (int x = 0; x < d->width; x++)
                memset(d->rows + (size_t)y * pitch + 3 * x, CHECKER_GREYS[(x / CHECKER + (y0 + y) / CHECKER) & 1], 3);
        SDL_UpdateTexture(d->texture, &(SDL_Rect){0, y0, d->width, rows}, d->rows, pitch);
    }
}

/* SDL started, and the window, its renderer and its texture made, on this
 * thread; the placeholder shown. False with d->why set otherwise. */
static bool open_window(display *d)
{
    /* glint catches the signals itself; the software renderer needs no
     * GPU driver (and leaves no driver's allocations behind at exit); the
     * screensaver is left alone, which keeps SDL off the session bus. */
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    SDL_SetHint(SDL_HINT_RENDER_DRIVER, "software");
    SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "linear");
    SDL_SetHint(SDL_HINT_VIDEO_ALLOW_SCREENSAVER, "1");
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0)
        return failed(d, "%s", SDL_GetError());
    /* Without a usable display SDL falls back to drivers that draw nowhere. */
    const char *driver = SDL_GetCurrentVideoDriver();
    if (!driver || strcmp(driver, "offscreen") == 0 || strcmp(driver, "dummy") == 0)
        return failed(d, "SDL found no screen to show it on (its video driver is '%s')", driver ? driver : "none");
    d->wake_event = SDL_RegisterEvents(1);
    if (d->wake_event == (Uint32)-1)
        return failed(d, "%s", SDL_GetError());
    /* SDL never shrinks a window to the screen: scaled here, keeping the aspect. */
    int w = d->width, h = d->height;
    SDL_Rect usable;
    if (SDL_GetDisplayUsableBounds(0, &usable) == 0 && usable.w > 0 && usable.h > 0 &&
        (w > usable.w || h > usable.h)) {
        double sx = (double)usable.w / w, sy = (double)usable.h / h, s = sx < sy ? sx : sy;
        w = (int)(w * s) > 0 ? (int)(w * s) : 1;
        h = (int)(h * s) > 0 ? (int)(h * s) : 1;
    }
    d->window = SDL_CreateWindow(d->title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, w, h, SDL_WINDOW_RESIZABLE);
    if (!d->window)
        return failed(d, "%s", SDL_GetError());
    d->renderer = SDL_CreateRenderer(d->window, -1, 0);
    if (!d->renderer)
        return failed(d, "%s", SDL_GetError());
    /* The image fills the window however it is sized, letterboxed to its aspect. */
    if (SDL_RenderSetLogicalSize(d->renderer, d->width, d->height) != 0)
        return failed(d, "%s", SDL_GetError());
    d->texture = SDL_CreateTexture(d->renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING, d->width, d->height);
    if (!d->texture)
        return failed(d, "%s", SDL_GetError());
    d->rows = malloc((size_t)3 * d->width * CHECKER);
    if (!d->rows)
        return failed(d, "out of memory");
    show_placeholder(d);
    SDL_RenderClear(d->renderer);
    SDL_RenderCopy(d->renderer, d->texture, NULL, NULL);
    SDL_RenderPresent(d->renderer);
    return true;
}

/* Puts a finished rectangle's pixels into the texture, CHECKER rows at a
 * time (the rows buffer is image-wide). Its pixels are final, so they are
 * read without the lock. */
static void show_rect(display *d, const tile_rect *t)
{
    int w = t->x1 - t->x0;
    for (int y0 = t->y0; y0 < t->y1; y0 += CHECKER) {
        int rows = t->y1 - y0 < CHECKER ? t->y1 - y0 : CHECKER;
        for (int y = 0; y < rows; y++)
            srgb_encode(d->rows + (size_t)y * 3 * w, d->pixels + 3 * ((size_t)(y0 + y) * d->width + t->x0),
                        (size_t)3 * w);
        SDL_UpdateTexture(d->texture, &(SDL_Rect){t->x0, y0, w, rows}, d->rows, 3 * w);
    }
}

/* Clears an unfinished progress line on a terminal before a message. */
static void clear_progress_line(void)
{
    if (isatty(STDERR_FILENO))
        fputs("\r\033[K", stderr);
}

/* s: writes the finished tiles as they are now (the rest black), saying
 * where on stderr. */
static void save_image(display *d)
{
    size_t values = (size_t)3 * d->width * d->height;
    glint_image shot = {d->width, d->height, malloc(values * sizeof(float))};
    clear_progress_line();
    if (!shot.pixels) {
        cli_complain(CLI_EXIT_INTERNAL, "s: out of memory for a copy of the image to save");
        return;
    }
    pthread_mutex_lock(&d->lock);
    memcpy(shot.pixels, d->pixels, values * sizeof(float));
    long long done = d->pixels_done;
    pthread_mutex_unlock(&d->lock);
    glint_error err = {0};
    if (glint_image_write_ex(&shot, d->save_path, &d->write_options, &err) != GLINT_OK)
        cli_complain(CLI_EXIT_IO, "s: the image was not saved: %s", err.message);
    else
        cli_complain(CLI_EXIT_OK, "s: saved the image (%d%% rendered) to %s",
                     (int)(done * 100 / ((long long)d->width * d->height)), d->save_path);
    free(shot.pixels);
}

/* What the user did since the last look at the window's events. */
typedef struct user_events {
    bool closed, save, exposed;
} user_events;

/* Waits up to timeout_ms for events (or a wake-up), then takes all there are. */
static user_events take_events(int timeout_ms)
{
    user_events u = {0};
    SDL_Event ev;
    if (!SDL_WaitEventTimeout(&ev, timeout_ms))
        return u;
    do {
        if (ev.type == SDL_QUIT || (ev.type == SDL_WINDOWEVENT && ev.window.event == SDL_WINDOWEVENT_CLOSE))
            u.closed = true;
        else if (ev.type == SDL_KEYDOWN && (ev.key.keysym.sym == SDLK_ESCAPE || ev.key.keysym.sym == SDLK_q))
            u.closed = true;
        else if (ev.type == SDL_KEYDOWN && ev.key.keysym.sym == SDLK_s && !ev.key.repeat)
            u.save = true;
        /* Nothing keeps an uncovered window's pixels: it is drawn again. */
        else if (ev.type == SDL_WINDOWEVENT &&
                 (ev.window.event == SDL_WINDOWEVENT_EXPOSED || ev.window.event == SDL_WINDOWEVENT_SIZE_CHANGED))
            u.exposed = true;
    } while (SDL_PollEvent(&ev));
    return u;
}

/* The window's loop, until the user closes it, a signal sets *cancel, or
 * display_close asks it to stop. */
static void show_until_closed(display *d)
{
    Uint64 last_frame = SDL_GetTicks64();
    int shown_percent = -1;
    bool shown_finished = false;
    for (;;) {
        Uint64 since = SDL_GetTicks64() - last_frame;
        user_events u = take_events(since >= FRAME_MS ? 1 : (int)(FRAME_MS - since));
        if (u.save)
            save_image(d);
        bool frame_due = SDL_GetTicks64() - last_frame >= FRAME_MS;
        pthread_mutex_lock(&d->lock);
        if (u.closed && !d->finished)
            *d->cancel = 1;
        bool leave = u.closed || d->stop || *d->cancel;
        size_t taken = 0;
        if (frame_due && !leave) {
            tile_rect *swap = d->taken;
            d->taken = d->fresh;
            d->fresh = swap;
            taken = d->fresh_count;
            d->fresh_count = 0;
        }
        int percent = (int)(d->pixels_done * 100 / ((long long)d->width * d->height));
        bool finished = d->finished;
        double seconds = d->seconds;
        if (leave)
            d->state = GONE;
        pthread_mutex_unlock(&d->lock);
        if (leave)
            return;
        for (size_t i = 0; i < taken; i++)
            show_rect(d, &d->taken[i]);
        if (taken > 0 || u.exposed) {
            SDL_RenderClear(d->renderer);
            SDL_RenderCopy(d->renderer, d->texture, NULL, NULL);
            SDL_RenderPresent(d->renderer);
        }
        if (frame_due)
            last_frame = SDL_GetTicks64();
        /* Set after the frame it describes is on screen. */
        if (percent != shown_percent || finished != shown_finished) {
            char title[sizeof d->title + 48];
            if (finished)
                snprintf(title, sizeof title, "%s - done in %.3f s", d->title, seconds);
            else
                snprintf(title, sizeof title, "%s - %d%%", d->title, percent);
            SDL_SetWindowTitle(d->window, title);
            shown_percent = percent;
            shown_finished = finished;
        }
    }
}

/* The window's thread: opens the window, says whether it did, shows it
 * until it is closed, and then leaves SDL. */
static void *window_thread(void *arg)
{
    display *d = arg;
    bool opened = open_window(d);
    pthread_mutex_lock(&d->lock);
    d->state = opened ? SHOWING : FAILED;
    pthread_cond_broadcast(&d->started);
    pthread_mutex_unlock(&d->lock);
    if (opened)
        show_until_closed(d);
    if (d->texture)
        SDL_DestroyTexture(d->texture);
    if (d->renderer)
        SDL_DestroyRenderer(d->renderer);
    if (d->window)
        SDL_DestroyWindow(d->window);
    SDL_Quit();
    return NULL;
}

/* Wakes the window's thread from its wait for events, while it has one. */
static void wake_locked(display *d)
{
    if (d->state == SHOWING)
        SDL_PushEvent(&(SDL_Event){.type = d->wake_event});
}

static void free_display(display *d)
{
    free(d->pixels);
    free(d->fresh);
    free(d->taken);
    free(d->rows);
    free(d->save_path);
    free(d);
}

/* "glint - NAME": the scene file's name without its folders, or the seed
 * room; bytes outside printable ASCII shown as '?', as X window titles
 * read by older tools are Latin-1. */
static void make_title(char *title, size_t size, const char *scene)
{
    const char *name = "seed room";
    if (scene) {
        const char *slash = strrchr(scene, '/');
        name = cli_scene_name(slash && slash[1] ? slash + 1 : scene);
    }
    int n = snprintf(title, size, "glint - %s", name);
    for (int i = 0; i < n && (size_t)i < size - 1; i++)
        if (title[i] < 0x20 || title[i] > 0x7e)
            title[i] = '?';
}

display *display_open(const cli_options *o, const cli_run *r, volatile sig_atomic_t *cancel, int *code)
{
    const char *x11 = getenv("DISPLAY"), *wayland = getenv("WAYLAND_DISPLAY");
    if ((!x11 || !*x11) && (!wayland || !*wayland)) {
        *code = cli_complain(CLI_EXIT_USAGE, "--display needs a screen, and neither DISPLAY nor WAYLAND_DISPLAY is set");
        return NULL;
    }
    display *d = calloc(1, sizeof *d);
    int w = r->settings.width, h = r->settings.height;
    if (d) {
        *d = (display){.width = w, .height = h, .cancel = cancel, .write_options = r->write_options};
        /* Tiles begin on multiples of 4 pixels: at most this many. */
        d->rect_capacity = (size_t)((w + 3) / 4) * (size_t)((h + 3) / 4);
        d->pixels = calloc((size_t)3 * w * h, sizeof(float));
        d->fresh = malloc(d->rect_capacity * sizeof(tile_rect));
        d->taken = malloc(d->rect_capacity * sizeof(tile_rect));
        d->save_path = strdup(strcmp(r->dest.path, "-") == 0 ? r->dest.default_path : r->dest.path);
    }
    if (!d || !d->pixels || !d->fresh || !d->taken || !d->save_path) {
        if (d)
            free_display(d);
        *code = cli_complain(CLI_EXIT_INTERNAL, "out of memory for the window's copy of the image");
        return NULL;
    }
    make_title(d->title, sizeof d->title, o->scene);
    pthread_mutex_init(&d->lock, NULL);
    pthread_cond_init(&d->started, NULL);
    /* Signals go to the render's threads, which act on them, not to the window's. */
    sigset_t all, before;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &before);
    int err = pthread_create(&d->thread, NULL, window_thread, d);
    pthread_sigmask(SIG_SETMASK, &before, NULL);
    if (err) {
        free_display(d);
        *code = cli_complain(CLI_EXIT_INTERNAL, "--display: no thread for the window: %s", strerror(err));
        return NULL;
    }
    pthread_mutex_lock(&d->lock);
    while (d->state == STARTING)
        pthread_cond_wait(&d->started, &d->lock);
    bool opened = d->state == SHOWING;
    pthread_mutex_unlock(&d->lock);
    if (!opened) {
        pthread_join(d->thread, NULL);
        *code = cli_complain(CLI_EXIT_USAGE, "--display: the window could not open: %s", d->why);
        free_display(d);
        return NULL;
    }
    return d;
}

void display_tile(void *user, int x0, int y0, int x1, int y1, const float *pixels, size_t stride)
{
    display *d = user;
    size_t row = (size_t)3 * (x1 - x0) * sizeof(float);
    pthread_mutex_lock(&d->lock);
    for (int y = y0; y < y1; y++)
        memcpy(d->pixels + 3 * ((size_t)y * d->width + x0), pixels + (size_t)(y - y0) * stride, row);
    /* Never full (tiles begin on multiples of 4); a tile past it would
     * only miss the window, never the saved image. */
    if (d->fresh_count < d->rect_capacity)
        d->fresh[d->fresh_count++] = (tile_rect){x0, y0, x1, y1};
    d->pixels_done += (long long)(x1 - x0) * (y1 - y0);
    pthread_mutex_unlock(&d->lock);
}

void display_finished(display *d, double seconds)
{
    pthread_mutex_lock(&d->lock);
    d->finished = true;
    d->seconds = seconds;
    wake_locked(d);
    pthread_mutex_unlock(&d->lock);
}

/* Joins the window's thread and frees the display. */
static void join_and_free(display *d)
{
    pthread_join(d->thread, NULL);
    pthread_mutex_destroy(&d->lock);
    pthread_cond_destroy(&d->started);
    free_display(d);
}

void display_wait(display *d)
{
    join_and_free(d);
}

void display_close(display *d)
{
    if (!d)
        return;
    pthread_mutex_lock(&d->lock);
    d->stop = true;
    wake_locked(d);
    pthread_mutex_unlock(&d->lock);
    join_and_free(d);
}
