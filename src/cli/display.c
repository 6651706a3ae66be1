/* display.c - the --display window (display.h). The render threads copy
 * each finished tile into the display's own float copy of the image and
 * list its rectangle; the window's thread, the only one calling SDL, takes
 * the new rectangles at most 30 times a second, draws them into the
 * window's surface (sRGB, scaled to the window by averaging each window
 * pixel's footprint) and sends the screen only those, so that a frame
 * costs what its new tiles do, not the window's size. The float copy is
 * what s saves: the finished tiles, black elsewhere, as --partial writes
 * them. The window's thread runs at a lower priority than the render's:
 * on a machine whose every core renders, the window may lag a moment
 * behind the render rather than slow it. */
#define _GNU_SOURCE /* gettid */
#include <pthread.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/resource.h>
#include <unistd.h>
#include "cli/display.h"
#include "cli/sdl_calls.h"
#include "image/srgb.h"
#include "render/film.h"

/* The shortest time between two frames of new tiles: 30 a second. */
#define FRAME_MS 33
/* The window thread's nice value: a tenth of a render thread's share of a
 * busy core (measured: the render of a 0.16 s 1080p frame, which the
 * window slowed by 15% at the render's priority, by 7% at this one). */
#define WINDOW_NICE 10
/* The placeholder: a checkerboard of squares this wide, in two dim greys. */
#define CHECKER 16
static const unsigned char CHECKER_GREYS[2] = {0x1c, 0x2c};

/* SDL was loaded and started on the window's thread (start_sdl). */
static bool sdl_loaded;

typedef struct tile_rect {
    int x0, y0, x1, y1;
} tile_rect;

/* Which image pixels each window pixel along one axis shows: window pixel
 * i averages image pixels lo[i] to hi[i] - 1 (one, the nearest, when the
 * window is the larger). Both never decrease with i. */
typedef struct axis_map {
    int window, image;
    int *lo, *hi;
} axis_map;

/* STARTING while the window's thread starts SDL; READY once it has, and
 * waits for the image's size (width > 0) to open the window; SHOWING once
 * it has; FAILED when either failed. */
enum display_state { STARTING, READY, SHOWING, FAILED };

struct display {
    int width, height;
    char title[128];                  /* "glint - NAME", ASCII */
    char *save_path;
    glint_image_write_options write_options;
    volatile sig_atomic_t *cancel;
    pthread_t thread;

    pthread_mutex_t lock;
    pthread_cond_t news;              /* the state changed, the size was given, or stop was set */
    /* Under the lock: */
    enum display_state state;
    char why[256];                    /* why the window did not open */
    float *pixels;                    /* the finished tiles, black elsewhere */
    tile_rect *rects;                 /* every finished tile, in the order finished */
    size_t rect_count, rect_capacity;
    long long pixels_done;
    bool finished, stop;
    double seconds;

    /* The window's thread alone: */
    SDL_Window *window;
    SDL_Surface *surface;             /* the window's pixels, SDL's */
    axis_map across, down;
    tile_rect *taken;                 /* rects[0 .. shown) copied: the tiles drawn */
    size_t shown, taken_capacity;
    SDL_Rect *changed;                /* the window rectangles drawn at this frame */
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

/* Fills m for a window `window` pixels long showing an image `image` long:
 * window pixel i starts at image pixel floor(i * image / window). False
 * when memory runs out. */
static bool map_axis(axis_map *m, int window, int image)
{
    free(m->lo);
    free(m->hi);
    m->window = window;
    m->image = image;
    m->lo = malloc((size_t)window * sizeof(int));
    m->hi = malloc((size_t)window * sizeof(int));
    if (!m->lo || !m->hi)
        return false;
    for (int i = 0; i < window; i++) {
        m->lo[i] = (int)((long long)i * image / window);
        int next = (int)((long long)(i + 1) * image / window);
        m->hi[i] = next > m->lo[i] ? next : m->lo[i] + 1;
    }
    return true;
}

/* The first i in [0, n) with v[i] >= value, else n (v never decreasing). */
static int first_at_least(const int *v, int n, int value)
{
    int lo = 0, hi = n;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (v[mid] >= value)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* The window pixels along m that show any of image pixels [a0, a1): [*w0, *w1). */
static void window_span(const axis_map *m, int a0, int a1, int *w0, int *w1)
{
    *w0 = first_at_least(m->hi, m->window, a0 + 1);
    *w1 = first_at_least(m->lo, m->window, a1);
}

/* Draws the window pixels that show any of the image's rectangle t, each
 * the average of its footprint's pixels within `within` (t itself while
 * other tiles may still be written; the whole image once all are final),
 * into the surface; *out, the window rectangle drawn. */
static void draw_rect(display *d, const tile_rect *t, const tile_rect *within, SDL_Rect *out)
{
    int wx0, wx1, wy0, wy1;
    window_span(&d->across, t->x0, t->x1, &wx0, &wx1);
    window_span(&d->down, t->y0, t->y1, &wy0, &wy1);
    SDL_Surface *s = d->surface;
    const SDL_PixelFormat *f = s->format;
    int bytes = f->BytesPerPixel;
    for (int wy = wy0; wy < wy1; wy++) {
        int y0 = d->down.lo[wy] > within->y0 ? d->down.lo[wy] : within->y0;
        int y1 = d->down.hi[wy] < within->y1 ? d->down.hi[wy] : within->y1;
        unsigned char *row = (unsigned char *)s->pixels + (size_t)wy * s->pitch;
        for (int wx = wx0; wx < wx1; wx++) {
            int x0 = d->across.lo[wx] > within->x0 ? d->across.lo[wx] : within->x0;
            int x1 = d->across.hi[wx] < within->x1 ? d->across.hi[wx] : within->x1;
            const float *p = d->pixels + 3 * ((size_t)y0 * d->width + x0);
            float rgb[3] = {p[0], p[1], p[2]};
            if (x1 - x0 > 1 || y1 - y0 > 1) {
                rgb[0] = rgb[1] = rgb[2] = 0;
                for (int y = y0; y < y1; y++)
                    for (int x = x0; x < x1; x++)
                        for (int c = 0; c < 3; c++)
                            rgb[c] += d->pixels[3 * ((size_t)y * d->width + x) + c];
                for (int c = 0; c < 3; c++)
                    rgb[c] /= (float)((x1 - x0) * (y1 - y0));
            }
            Uint8 r = srgb_byte(rgb[0]), g = srgb_byte(rgb[1]), b = srgb_byte(rgb[2]);
            /* SDL_MapRGB's own formula, inline, but for palettes. */
            Uint32 v = f->palette ? sdl->MapRGB(f, r, g, b)
                                  : (Uint32)(r >> f->Rloss) << f->Rshift | (Uint32)(g >> f->Gloss) << f->Gshift |
                                        (Uint32)(b >> f->Bloss) << f->Bshift | f->Amask;
            memcpy(row + (size_t)wx * bytes, &v, (size_t)bytes); /* little-endian: the low bytes */
        }
    }
    *out = (SDL_Rect){wx0, wy0, wx1 - wx0, wy1 - wy0};
}

/* Fills the whole surface with the placeholder. */
static void draw_placeholder(display *d)
{
    SDL_Surface *s = d->surface;
    Uint32 grey[2];
    for (int k = 0; k < 2; k++)
        grey[k] = sdl->MapRGB(s->format, CHECKER_GREYS[k], CHECKER_GREYS[k], CHECKER_GREYS[k]);
    for (int y = 0; y < s->h; y += CHECKER)
        for (int x = 0; x < s->w; x += CHECKER)
            sdl->FillRect(s, &(SDL_Rect){x, y, CHECKER, CHECKER}, grey[(x / CHECKER + y / CHECKER) & 1]);
}

/* The window's surface taken again (it is SDL's, and changes with the
 * window's size) and drawn whole: the placeholder, and the tiles drawn so
 * far, or, once the render is over, the image. False when memory runs out. */
static bool draw_all(display *d, bool finished)
{
    d->surface = sdl->GetWindowSurface(d->window);
    if (!d->surface || !map_axis(&d->across, d->surface->w, d->width) ||
        !map_axis(&d->down, d->surface->h, d->height))
        return false;
    SDL_Rect ignored;
    if (finished) {
        tile_rect all = {0, 0, d->width, d->height};
        draw_rect(d, &all, &all, &ignored);
    } else {
        draw_placeholder(d);
        for (size_t i = 0; i < d->shown; i++)
            draw_rect(d, &d->taken[i], &d->taken[i], &ignored);
    }
    return true;
}

/* SDL started on this thread; false with d->why set otherwise. */
static bool start_sdl(display *d)
{
    glint_error err;
    if (!sdl_calls_load(&err))
        return failed(d, "%s", err.message);
    sdl_loaded = true;
    /* glint catches the signals itself; the window's pixels are SDL's
     * surface, never a GPU driver's (none is needed, and none leaves its
     * allocations behind at exit); the screensaver is left alone, which
     * keeps SDL off the session bus. */
    sdl->SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    sdl->SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
    sdl->SetHint(SDL_HINT_VIDEO_ALLOW_SCREENSAVER, "1");
    if (sdl->InitSubSystem(SDL_INIT_VIDEO) != 0)
        return failed(d, "%s", sdl->GetError());
    /* Without a usable display SDL falls back to drivers that draw nowhere. */
    const char *driver = sdl->GetCurrentVideoDriver();
    if (!driver || strcmp(driver, "offscreen") == 0 || strcmp(driver, "dummy") == 0)
        return failed(d, "SDL found no screen to show it on (its video driver is '%s')", driver ? driver : "none");
    return true;
}

/* The window made, sized to the image or scaled down to fit the screen,
 * and the placeholder shown; false with d->why set otherwise. */
static bool open_window(display *d)
{
    /* SDL never shrinks a window to the screen: scaled here, keeping the aspect. */
    int w = d->width, h = d->height;
    SDL_Rect usable;
    if (sdl->GetDisplayUsableBounds(0, &usable) == 0 && usable.w > 0 && usable.h > 0 &&
        (w > usable.w || h > usable.h)) {
        double sx = (double)usable.w / w, sy = (double)usable.h / h, scale = sx < sy ? sx : sy;
        w = (int)(w * scale) > 0 ? (int)(w * scale) : 1;
        h = (int)(h * scale) > 0 ? (int)(h * scale) : 1;
    }
    d->window = sdl->CreateWindow(d->title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, w, h, 0);
    if (!d->window)
        return failed(d, "%s", sdl->GetError());
    if (!draw_all(d, false))
        return failed(d, "%s", d->surface ? "out of memory" : sdl->GetError());
    sdl->UpdateWindowSurface(d->window);
    return true;
}

/* Copies the tiles finished since the last frame into d->taken, under the
 * lock; their count. 0, taking none, when memory runs out (they are taken
 * at a later frame, or drawn with the whole image at the end). */
static size_t take_new_tiles_locked(display *d)
{
    size_t fresh = d->rect_count - d->shown;
    if (d->rect_count > d->taken_capacity) {
        tile_rect *taken = realloc(d->taken, d->rect_capacity * sizeof *taken);
        SDL_Rect *changed = realloc(d->changed, d->rect_capacity * sizeof *changed);
        if (taken)
            d->taken = taken;
        if (changed)
            d->changed = changed;
        if (!taken || !changed)
            return 0;
        d->taken_capacity = d->rect_capacity;
    }
    if (fresh > 0)
        memcpy(d->taken + d->shown, d->rects + d->shown, fresh * sizeof *d->taken);
    return fresh;
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
    glint_image shot = {d->width, d->height, film_pixels_alloc(d->width, d->height, true)};
    clear_progress_line();
    if (!shot.pixels) {
        cli_complain(CLI_EXIT_INTERNAL, "s: out of memory for a copy of the image to save");
        return;
    }
    /* The listed tiles alone: others may be being copied in. */
    pthread_mutex_lock(&d->lock);
    for (size_t i = 0; i < d->rect_count; i++) {
        const tile_rect *t = &d->rects[i];
        for (int y = t->y0; y < t->y1; y++) {
            size_t at = 3 * ((size_t)y * d->width + t->x0);
            memcpy(shot.pixels + at, d->pixels + at, (size_t)3 * (t->x1 - t->x0) * sizeof(float));
        }
    }
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
    bool closed, save, exposed, resized;
} user_events;

/* Takes all the events there are. */
static user_events take_events(void)
{
    user_events u = {0};
    SDL_Event ev;
    while (sdl->PollEvent(&ev)) {
        if (ev.type == SDL_QUIT || (ev.type == SDL_WINDOWEVENT && ev.window.event == SDL_WINDOWEVENT_CLOSE))
            u.closed = true;
        else if (ev.type == SDL_KEYDOWN && (ev.key.keysym.sym == SDLK_ESCAPE || ev.key.keysym.sym == SDLK_q))
            u.closed = true;
        else if (ev.type == SDL_KEYDOWN && ev.key.keysym.sym == SDLK_s && !ev.key.repeat)
            u.save = true;
        /* Nothing keeps an uncovered window's pixels: they are sent again. */
        else if (ev.type == SDL_WINDOWEVENT && ev.window.event == SDL_WINDOWEVENT_EXPOSED)
            u.exposed = true;
        /* A window manager may resize it: it is drawn again, to the new size. */
        else if (ev.type == SDL_WINDOWEVENT && ev.window.event == SDL_WINDOWEVENT_SIZE_CHANGED)
            u.resized = true;
    }
    return u;
}

/* Waits, under the lock, until the next frame is due or there is news (the
 * render over, a stop). SDL's own wait is not used: in SDL 2.26 waking it
 * from another thread can send an event to a window already destroyed,
 * which Xlib makes fatal; this way no other thread calls SDL at all. */
static void wait_for_frame_locked(display *d, bool finished_shown)
{
    struct timespec until;
    clock_gettime(CLOCK_MONOTONIC, &until);
    until.tv_nsec += FRAME_MS * 1000000L;
    if (until.tv_nsec >= 1000000000L) {
        until.tv_sec++;
        until.tv_nsec -= 1000000000L;
    }
    while (!d->stop && !*d->cancel && d->finished == finished_shown &&
           pthread_cond_timedwait(&d->news, &d->lock, &until) == 0) {
    }
}

/* The window's loop, until the user closes it, a signal sets *cancel, or
 * display_close asks it to stop: once a frame (30 a second at most), or
 * at once when the render is over. */
static void show_until_closed(display *d)
{
    int shown_percent = -1;
    bool shown_finished = false;
    for (;;) {
        user_events u = take_events();
        if (u.save)
            save_image(d);
        pthread_mutex_lock(&d->lock);
        if (u.closed && !d->finished)
            *d->cancel = 1;
        bool leave = u.closed || d->stop || *d->cancel;
        size_t fresh = leave ? 0 : take_new_tiles_locked(d);
        int percent = (int)(d->pixels_done * 100 / ((long long)d->width * d->height));
        bool finished = d->finished;
        double seconds = d->seconds;
        pthread_mutex_unlock(&d->lock);
        if (leave)
            return;
        /* Once the render is over every pixel is final: the whole image
         * is drawn, each window pixel from its whole footprint. */
        if (u.resized || (finished && !shown_finished)) {
            d->shown += fresh;
            if (!draw_all(d, finished)) {
                clear_progress_line();
                cli_complain(CLI_EXIT_INTERNAL, "--display: the window closed, out of memory to draw it");
                return;
            }
            sdl->UpdateWindowSurface(d->window);
        } else {
            for (size_t i = 0; i < fresh; i++)
                draw_rect(d, &d->taken[d->shown + i], &d->taken[d->shown + i], &d->changed[i]);
            d->shown += fresh;
            if (u.exposed)
                sdl->UpdateWindowSurface(d->window);
            else if (fresh > 0)
                sdl->UpdateWindowSurfaceRects(d->window, d->changed, (int)fresh);
        }
        /* Set after the frame it describes is on screen. */
        if (percent != shown_percent || finished != shown_finished) {
            char title[sizeof d->title + 48];
            if (finished)
                snprintf(title, sizeof title, "%s - done in %.3f s", d->title, seconds);
            else
                snprintf(title, sizeof title, "%s - %d%%", d->title, percent);
            sdl->SetWindowTitle(d->window, title);
            shown_percent = percent;
            shown_finished = finished;
        }
        pthread_mutex_lock(&d->lock);
        wait_for_frame_locked(d, shown_finished);
        pthread_mutex_unlock(&d->lock);
    }
}

/* Sets the state and says so, under the lock. */
static void set_state_locked(display *d, enum display_state state)
{
    d->state = state;
    pthread_cond_broadcast(&d->news);
}

/* The window's thread: starts SDL (while the scene loads), opens the
 * window once it knows the image's size, says whether it did, shows it
 * until it is closed, and then leaves SDL. */
static void *window_thread(void *arg)
{
    display *d = arg;
    bool ok = start_sdl(d);
    pthread_mutex_lock(&d->lock);
    set_state_locked(d, ok ? READY : FAILED);
    while (ok && d->width == 0 && !d->stop)
        pthread_cond_wait(&d->news, &d->lock);
    ok = ok && !d->stop;
    pthread_mutex_unlock(&d->lock);
    if (ok) {
        ok = open_window(d);
        pthread_mutex_lock(&d->lock);
        set_state_locked(d, ok ? SHOWING : FAILED);
        pthread_mutex_unlock(&d->lock);
    }
    /* Lowered only once the window is open: the render waits for it, and
     * at this priority SDL's start lags on a machine busy with other work
     * (two cores, six busy processes: a 64x48 frame shown done after 1.5 s
     * instead of 0.95 s; beside the MPI tests, an ASan build's window once
     * did not show within tests/cli/display.sh's wait).
     * Linux's nice is per thread; no matter if it is refused. */
    if (ok) {
        setpriority(PRIO_PROCESS, (id_t)gettid(), WINDOW_NICE);
        show_until_closed(d);
    }
    if (d->window)
        sdl->DestroyWindow(d->window);
    if (sdl_loaded)
        sdl->Quit();
    return NULL;
}

static void free_display(display *d)
{
    free(d->pixels);
    free(d->rects);
    free(d->taken);
    free(d->changed);
    free(d->across.lo);
    free(d->across.hi);
    free(d->down.lo);
    free(d->down.hi);
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

display *display_start(volatile sig_atomic_t *cancel, int *code)
{
    const char *x11 = getenv("DISPLAY"), *wayland = getenv("WAYLAND_DISPLAY");
    if ((!x11 || !*x11) && (!wayland || !*wayland)) {
        *code = cli_complain(CLI_EXIT_USAGE, "--display needs a screen, and neither DISPLAY nor WAYLAND_DISPLAY is set");
        return NULL;
    }
    /* SDL asks the session's D-Bus for an input method. Where no session
     * bus is named, libdbus would start one: it forks this threaded
     * process to run dbus-launch, and under AddressSanitizer the child
     * has hung before its exec, the window never opening. glint needs no
     * bus: an address that names none makes libdbus give up at once. Set
     * before the window's thread starts (glint's own threads start later). */
    if (!getenv("DBUS_SESSION_BUS_ADDRESS"))
        setenv("DBUS_SESSION_BUS_ADDRESS", "disabled:", 0);
    display *d = calloc(1, sizeof *d);
    if (!d) {
        *code = cli_complain(CLI_EXIT_INTERNAL, "out of memory for the window");
        return NULL;
    }
    d->cancel = cancel;
    pthread_mutex_init(&d->lock, NULL);
    pthread_condattr_t monotonic;
    pthread_condattr_init(&monotonic);
    pthread_condattr_setclock(&monotonic, CLOCK_MONOTONIC);
    pthread_cond_init(&d->news, &monotonic);
    pthread_condattr_destroy(&monotonic);
    /* Signals go to the render's threads, which act on them, not to the window's. */
    sigset_t all, before;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &before);
    int err = pthread_create(&d->thread, NULL, window_thread, d);
    pthread_sigmask(SIG_SETMASK, &before, NULL);
    if (err) {
        pthread_mutex_destroy(&d->lock);
        pthread_cond_destroy(&d->news);
        free(d);
        *code = cli_complain(CLI_EXIT_INTERNAL, "--display: no thread for the window: %s", strerror(err));
        return NULL;
    }
    return d;
}

bool display_show(display *d, const cli_options *o, const cli_run *r, int *code)
{
    int w = r->settings.width, h = r->settings.height;
    float *pixels = film_pixels_alloc(w, h, true);
    char *save_path = strdup(strcmp(r->dest.path, "-") == 0 ? r->dest.default_path : r->dest.path);
    if (!pixels || !save_path) {
        free(pixels);
        free(save_path);
        display_close(d);
        *code = cli_complain(CLI_EXIT_INTERNAL, "out of memory for the window's copy of the image");
        return false;
    }
    pthread_mutex_lock(&d->lock);
    d->pixels = pixels;
    d->save_path = save_path;
    d->write_options = r->write_options;
    make_title(d->title, sizeof d->title, o->scene);
    d->width = w;
    d->height = h;
    pthread_cond_broadcast(&d->news);
    pthread_mutex_unlock(&d->lock);
    /* While the window opens, the copy's pages are made ready, which the
     * render threads would otherwise wait for. */
    for (size_t at = 0; at < (size_t)12 * w * h; at += 4096)
        ((volatile char *)pixels)[at] = 0;
    pthread_mutex_lock(&d->lock);
    while (d->state == STARTING || d->state == READY)
        pthread_cond_wait(&d->news, &d->lock);
    bool opened = d->state == SHOWING;
    pthread_mutex_unlock(&d->lock);
    if (!opened) {
        *code = cli_complain(CLI_EXIT_USAGE, "--display: the window could not open: %s", d->why);
        display_close(d);
    }
    return opened;
}

void display_tile(void *user, int x0, int y0, int x1, int y1, const float *pixels, size_t stride)
{
    display *d = user;
    size_t row = (size_t)3 * (x1 - x0) * sizeof(float);
    /* Outside the lock: no one reads a tile's pixels before it is listed. */
    for (int y = y0; y < y1; y++)
        memcpy(d->pixels + 3 * ((size_t)y * d->width + x0), pixels + (size_t)(y - y0) * stride, row);
    pthread_mutex_lock(&d->lock);
    /* Without memory for a longer list, the tile misses the window, and
     * what s saves, until the render is over. */
    if (d->rect_count == d->rect_capacity) {
        size_t capacity = d->rect_capacity ? 2 * d->rect_capacity : 256;
        tile_rect *rects = realloc(d->rects, capacity * sizeof *rects);
        if (rects) {
            d->rects = rects;
            d->rect_capacity = capacity;
        }
    }
    if (d->rect_count < d->rect_capacity)
        d->rects[d->rect_count++] = (tile_rect){x0, y0, x1, y1};
    d->pixels_done += (long long)(x1 - x0) * (y1 - y0);
    pthread_mutex_unlock(&d->lock);
}

void display_finished(display *d, double seconds)
{
    pthread_mutex_lock(&d->lock);
    d->finished = true;
    d->seconds = seconds;
    pthread_cond_broadcast(&d->news);
    pthread_mutex_unlock(&d->lock);
}

/* Joins the window's thread and frees the display. */
static void join_and_free(display *d)
{
    pthread_join(d->thread, NULL);
    pthread_mutex_destroy(&d->lock);
    pthread_cond_destroy(&d->news);
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
    pthread_cond_broadcast(&d->news);
    pthread_mutex_unlock(&d->lock);
    join_and_free(d);
}
