/* xdnd_drop: drops files on the X window at a point, as a file manager's drag would (XDND version 5,
 * https://freedesktop.org/wiki/Specifications/XDND/). The UI tests use it because xdotool moves the
 * pointer but cannot drag data from one program to another.
 *
 *   xdnd_drop [--timeout S] X Y PATH...
 *
 * X Y are root-window coordinates. Exit status 0 when the window there accepted the drop and said it
 * finished; otherwise one line on stderr saying why, and status 1 (2 for a bad command line).
 *
 * The protocol, as this program drives it (the source is us, the target the window under X,Y):
 *   1. The target advertises XDND by an XdndAware property (its highest version) on its top-level window.
 *   2. The source owns the XdndSelection selection: the dropped data is read from it, like a copy-paste.
 *   3. XdndEnter    source -> target  "a drag came in; it offers these types" (text/uri-list here).
 *   4. XdndPosition source -> target  "the pointer is at X,Y; I would like to copy".
 *   5. XdndStatus   target -> source  "I accept (or refuse) a drop there".
 *   6. XdndDrop     source -> target  "the button was released": the target asks for the selection...
 *   7. SelectionRequest -> source: the source writes the URI list on the target's window and says so.
 *   8. XdndFinished target -> source  "I have the data; the drag is over".
 *   A refused drag ends with XdndLeave instead of XdndDrop. */
#define _POSIX_C_SOURCE 200809L

#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/select.h>
#include <time.h>
#include <unistd.h>

#define XDND_VERSION 5

typedef struct Atoms {
    Atom aware, selection, enter, position, status, drop, finished, leave, action_copy;
    Atom uri_list, targets, timestamp_probe;
} Atoms;

static const char* program = "xdnd_drop";

/* An X protocol error (the target window vanished mid-drag, say) ends the drag with its description. */
static int on_x_error(Display* display, XErrorEvent* error) {
    char text[256];
    XGetErrorText(display, error->error_code, text, sizeof text);
    fprintf(stderr, "%s: X error during the drag: %s (request %d)\n", program, text, error->request_code);
    exit(1);
}

static double now_seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* The next event, waiting at most until `deadline` (now_seconds()); 0 when none came in time. */
static int next_event(Display* display, XEvent* event, double deadline) {
    while (!XPending(display)) { /* XPending also sends what is still buffered */
        double const left = deadline - now_seconds();
        if (left <= 0.0) return 0;
        fd_set readable;
        FD_ZERO(&readable);
        FD_SET(ConnectionNumber(display), &readable);
        struct timeval wait = {(time_t)left, (suseconds_t)((left - (double)(time_t)left) * 1e6)};
        if (select(ConnectionNumber(display) + 1, &readable, NULL, NULL, &wait) < 0 && errno != EINTR) return 0;
    }
    XNextEvent(display, event);
    return 1;
}

/* --- the dropped data: text/uri-list ------------------------------------------------------------- */

/* RFC 3986's unreserved characters and '/' stay as they are; every other byte becomes %XX, so a path
 * with spaces, '%' or non-ASCII names survives (the target decodes %XX back). */
static int keeps_as_is(unsigned char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '.' ||
           c == '_' || c == '~' || c == '/';
}

/* "file:///abs/path\r\n" for each path (RFC 2483: text/uri-list lines end with CRLF). Relative paths
 * are made absolute against the current folder; a URI names a file from the root. Caller frees. */
static char* uri_list(int count, char** paths) {
    char cwd[4096];
    if (!getcwd(cwd, sizeof cwd)) cwd[0] = '\0';
    size_t size = 1;
    for (int i = 0; i < count; ++i) size += strlen("file://") + 3 * (strlen(cwd) + 1 + strlen(paths[i])) + 2;
    char* out = malloc(size);
    if (!out) return NULL;
    char* o = out;
    for (int i = 0; i < count; ++i) {
        char const* parts[3] = {paths[i][0] == '/' ? "" : cwd, paths[i][0] == '/' ? "" : "/", paths[i]};
        o += sprintf(o, "file://");
        for (int p = 0; p < 3; ++p)
            for (unsigned char const* c = (unsigned char const*)parts[p]; *c; ++c)
                o += keeps_as_is(*c) ? sprintf(o, "%c", *c) : sprintf(o, "%%%02X", *c);
        o += sprintf(o, "\r\n");
    }
    *o = '\0';
    return out;
}

/* --- finding the target ------------------------------------------------------------------------ */

/* The XDND version the window advertises in its XdndAware property, 0 when it has none. */
static int xdnd_version(Display* display, Window window, Atoms const* a) {
    Atom type = None;
    int format = 0;
    unsigned long items = 0, after = 0;
    unsigned char* data = NULL;
    int version = 0;
    int const got =
        XGetWindowProperty(display, window, a->aware, 0, 1, False, XA_ATOM, &type, &format, &items, &after, &data);
    if (got == Success && type == XA_ATOM && format == 32 && items == 1) version = (int)*(Atom*)data;
    if (data) XFree(data);
    return version;
}

/* The window under root coordinates x,y that takes drops: from the root down through the mapped child
 * under the point at each level (the topmost one), the first with XdndAware. GLFW sets XdndAware on its
 * top-level window; under a window manager that one sits inside the manager's frame, hence the walk.
 * XdndProxy (a window that forwards another's drops) is not followed: GLFW sets none. */
static Window find_target(Display* display, Window root, int x, int y, Atoms const* a, int* version) {
    Window window = root;
    for (;;) {
        Window child = None;
        int wx = 0, wy = 0;
        if (!XTranslateCoordinates(display, root, window, x, y, &wx, &wy, &child) || child == None) return None;
        if ((*version = xdnd_version(display, child, a)) > 0) return child;
        window = child;
    }
}

/* --- the protocol's messages ---------------------------------------------------------------------- */

/* One XDND ClientMessage to the target: l[0] is always the source window, the rest per message. */
static void send_xdnd(Display* display, Window target, Atom type, Window source, long l1, long l2, long l3, long l4) {
    XEvent e;
    memset(&e, 0, sizeof e);
    e.xclient.type = ClientMessage;
    e.xclient.window = target;
    e.xclient.message_type = type;
    e.xclient.format = 32;
    e.xclient.data.l[0] = (long)source;
    e.xclient.data.l[1] = l1;
    e.xclient.data.l[2] = l2;
    e.xclient.data.l[3] = l3;
    e.xclient.data.l[4] = l4;
    XSendEvent(display, target, False, NoEventMask, &e);
    XFlush(display);
}

/* A server timestamp for taking the selection (ICCCM: never CurrentTime): the time of a PropertyNotify
 * that an empty append to a property of our own window produces. */
static Time server_time(Display* display, Window source, Atoms const* a) {
    XEvent e;
    XChangeProperty(display, source, a->timestamp_probe, XA_STRING, 8, PropModeAppend, NULL, 0);
    do {
        XWindowEvent(display, source, PropertyChangeMask, &e);
    } while (e.type != PropertyNotify || e.xproperty.atom != a->timestamp_probe);
    return e.xproperty.time;
}

/* Step 7: the target converts XdndSelection to text/uri-list into a property of its window; we write the
 * list there and tell it with a SelectionNotify. TARGETS (what can you give?) is answered too; anything
 * else is refused with property None, as ICCCM says. */
static void answer_selection_request(Display* display, XSelectionRequestEvent const* r, Atoms const* a,
                                     char const* uris) {
    XEvent reply;
    memset(&reply, 0, sizeof reply);
    reply.xselection.type = SelectionNotify;
    reply.xselection.requestor = r->requestor;
    reply.xselection.selection = r->selection;
    reply.xselection.target = r->target;
    reply.xselection.time = r->time;
    reply.xselection.property = r->property != None ? r->property : r->target; /* None: an old client */
    if (r->selection == a->selection && r->target == a->uri_list) {
        XChangeProperty(display, r->requestor, reply.xselection.property, a->uri_list, 8, PropModeReplace,
                        (unsigned char const*)uris, (int)strlen(uris));
    } else if (r->selection == a->selection && r->target == a->targets) {
        Atom const offered[2] = {a->targets, a->uri_list};
        XChangeProperty(display, r->requestor, reply.xselection.property, XA_ATOM, 32, PropModeReplace,
                        (unsigned char const*)offered, 2);
    } else {
        reply.xselection.property = None;
    }
    XSendEvent(display, r->requestor, False, NoEventMask, &reply);
    XFlush(display);
}

/* Steps 3 to 8 with the target found at x,y; returns the exit status. */
static int drag(Display* display, Atoms const* a, int x, int y, int count, char const* uris, double timeout) {
    Window const root = DefaultRootWindow(display);
    int target_version = 0;
    Window const target = find_target(display, root, x, y, a, &target_version);
    if (target == None) {
        fprintf(stderr, "%s: no window that takes drops (XdndAware) at %d,%d\n", program, x, y);
        return 1;
    }
    /* Both sides speak the lower of their versions; GLFW ignores messages of a version above its own. */
    int const version = target_version < XDND_VERSION ? target_version : XDND_VERSION;

    /* The source: an unmapped window of our own that owns the selection and receives the replies. */
    Window const source = XCreateSimpleWindow(display, root, 0, 0, 1, 1, 0, 0, 0);
    XSelectInput(display, source, PropertyChangeMask);
    Time const time = server_time(display, source, a);
    XSetSelectionOwner(display, a->selection, source, time); /* step 2 */
    if (XGetSelectionOwner(display, a->selection) != source) {
        fprintf(stderr, "%s: could not own XdndSelection\n", program);
        return 1;
    }

    /* Step 3: l[1] = version << 24 with bit 0 clear (three types or fewer, all in l[2..4]). */
    send_xdnd(display, target, a->enter, source, (long)version << 24, (long)a->uri_list, None, None);
    /* Step 4: l[2] = x << 16 | y in root coordinates, l[3] the time, l[4] the action we ask for. */
    send_xdnd(display, target, a->position, source, 0, ((long)x << 16) | (y & 0xffff), (long)time,
              (long)a->action_copy);

    double const deadline = now_seconds() + timeout;
    int dropped = 0; /* step 6 sent */
    XEvent e;
    while (next_event(display, &e, deadline)) {
        if (e.type == SelectionRequest) {
            answer_selection_request(display, &e.xselectionrequest, a, uris);
            continue;
        }
        if (e.type != ClientMessage || (Window)e.xclient.data.l[0] != target) continue;
        if (e.xclient.message_type == a->status && !dropped) {
            /* Step 5: bit 0 of l[1] says whether the target would take a drop at this point. */
            if (!(e.xclient.data.l[1] & 1)) {
                send_xdnd(display, target, a->leave, source, 0, 0, 0, 0);
                fprintf(stderr, "%s: window 0x%lx at %d,%d refused the drag (XdndStatus without accept)\n", program,
                        (unsigned long)target, x, y);
                return 1;
            }
            /* Step 6: the button is released here; l[2] is the time the target converts the selection at. */
            send_xdnd(display, target, a->drop, source, 0, (long)time, 0, 0);
            dropped = 1;
        } else if (e.xclient.message_type == a->finished && dropped) {
            /* Step 8. Version 5 puts "accepted and done" in bit 0 of l[1]. GLFW (3.3, 3.4) puts the number of
             * bytes it read there instead, so any non-zero value is taken as success, 0 as failure. */
            if (version >= 5 && e.xclient.data.l[1] == 0) {
                fprintf(stderr, "%s: window 0x%lx finished the drop without taking it (XdndFinished l[1] = 0)\n",
                        program, (unsigned long)target);
                return 1;
            }
            printf("%s: window 0x%lx (%lu) took the drop of %d path(s) at %d,%d\n", program, (unsigned long)target,
                   (unsigned long)target, count, x, y);
            return 0;
        }
    }
    if (!dropped) send_xdnd(display, target, a->leave, source, 0, 0, 0, 0);
    fprintf(stderr, "%s: window 0x%lx at %d,%d sent no %s within %g s\n", program, (unsigned long)target, x, y,
            dropped ? "XdndFinished after the drop" : "XdndStatus", timeout);
    return 1;
}

/* A whole number from a command-line argument, or 0 with *ok cleared. */
static long whole_number(char const* text, int* ok) {
    char* end = NULL;
    long const value = strtol(text, &end, 10);
    if (end == text || *end != '\0') *ok = 0;
    return value;
}

static int usage(void) {
    fprintf(stderr, "usage: %s [--timeout SECONDS] X Y PATH...   (X Y in root-window coordinates)\n", program);
    return 2;
}

int main(int argc, char** argv) {
    double timeout = 30.0;
    int arg = 1;
    if (arg + 1 < argc && strcmp(argv[arg], "--timeout") == 0) {
        timeout = atof(argv[arg + 1]);
        arg += 2;
    }
    if (argc - arg < 3 || timeout <= 0.0) return usage();
    int ok = 1;
    int const x = (int)whole_number(argv[arg], &ok), y = (int)whole_number(argv[arg + 1], &ok);
    if (!ok) return usage();
    int const count = argc - arg - 2;

    Display* display = XOpenDisplay(NULL);
    if (!display) {
        fprintf(stderr, "%s: cannot open the X display \"%s\"\n", program, XDisplayName(NULL));
        return 1;
    }
    XSetErrorHandler(on_x_error);
    Atoms a;
    a.aware = XInternAtom(display, "XdndAware", False);
    a.selection = XInternAtom(display, "XdndSelection", False);
    a.enter = XInternAtom(display, "XdndEnter", False);
    a.position = XInternAtom(display, "XdndPosition", False);
    a.status = XInternAtom(display, "XdndStatus", False);
    a.drop = XInternAtom(display, "XdndDrop", False);
    a.finished = XInternAtom(display, "XdndFinished", False);
    a.leave = XInternAtom(display, "XdndLeave", False);
    a.action_copy = XInternAtom(display, "XdndActionCopy", False);
    a.uri_list = XInternAtom(display, "text/uri-list", False);
    a.targets = XInternAtom(display, "TARGETS", False);
    a.timestamp_probe = XInternAtom(display, "XDND_DROP_TIMESTAMP", False);
    char* const uris = uri_list(count, argv + arg + 2);
    int status = 1;
    if (uris)
        status = drag(display, &a, x, y, count, uris, timeout);
    else
        fprintf(stderr, "%s: out of memory\n", program);
    free(uris);
    XCloseDisplay(display); /* also destroys the source window and gives up the selection */
    return status;
}
