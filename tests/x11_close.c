/* x11_close.c - asks an X window to close as a window manager does when its
 * user clicks the close button: a WM_DELETE_WINDOW message, which the
 * program may act on (xdotool's windowclose destroys the window instead).
 * For tests/cli/display.sh, under Xvfb, where no window manager runs.
 * Usage: x11_close WINDOW-ID (decimal or 0x hex); exit 0 once sent. */
#include <X11/Xlib.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    char *end;
    unsigned long id = argc == 2 ? strtoul(argv[1], &end, 0) : 0;
    if (argc != 2 || *end || id == 0) {
        fputs("usage: x11_close WINDOW-ID\n", stderr);
        return 2;
    }
    Display *x = XOpenDisplay(NULL);
    if (!x) {
        fputs("x11_close: cannot open the display\n", stderr);
        return 1;
    }
    XEvent ev = {0};
    ev.xclient.type = ClientMessage;
    ev.xclient.window = (Window)id;
    ev.xclient.message_type = XInternAtom(x, "WM_PROTOCOLS", False);
    ev.xclient.format = 32;
    ev.xclient.data.l[0] = (long)XInternAtom(x, "WM_DELETE_WINDOW", False);
    ev.xclient.data.l[1] = CurrentTime;
    Status sent = XSendEvent(x, (Window)id, False, NoEventMask, &ev);
    XSync(x, False);
    XCloseDisplay(x);
    return sent ? 0 : 1;
}
