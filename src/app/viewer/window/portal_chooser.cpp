// portal_chooser.cpp - the XDG desktop portal's FileChooser through libportal (Debian 12:
// 0.6), on the chooser's worker thread with a GLib main context of its own, so the UI thread
// never blocks and GLib never needs the application's main loop. libportal 0.6 has no way to
// say there is no session bus (it warns and keeps a null connection), so the bus and the
// portal's name are checked here first; a missing portal falls back to zenity.
#include <gio/gio.h>
#include <libportal/portal.h>

#include "app/viewer/window/file_chooser.h"

namespace app {
namespace {

// Whether a session bus answers and the portal runs or can be started on it.
bool portalReachable() {
    GError* error = nullptr;
    GDBusConnection* bus = g_bus_get_sync(G_BUS_TYPE_SESSION, nullptr, &error);
    if (!bus) {
        g_clear_error(&error);
        return false;
    }
    bool found = false;
    for (const char* method : {"NameHasOwner", "ListActivatableNames"}) {
        const bool owner = method[0] == 'N';
        GVariant* reply = g_dbus_connection_call_sync(
            bus, "org.freedesktop.DBus", "/org/freedesktop/DBus", "org.freedesktop.DBus", method,
            owner ? g_variant_new("(s)", "org.freedesktop.portal.Desktop") : nullptr,
            owner ? G_VARIANT_TYPE("(b)") : G_VARIANT_TYPE("(as)"), G_DBUS_CALL_FLAGS_NONE, 2000,
            nullptr, &error);
        g_clear_error(&error);
        if (!reply) continue;
        if (owner) {
            gboolean has = FALSE;
            g_variant_get(reply, "(b)", &has);
            found = found || has;
        } else {
            GVariantIter* names = nullptr;
            const char* name = nullptr;
            g_variant_get(reply, "(as)", &names);
            while (g_variant_iter_loop(names, "&s", &name))
                found = found || g_str_equal(name, "org.freedesktop.portal.Desktop");
            g_variant_iter_free(names);
        }
        g_variant_unref(reply);
    }
    g_object_unref(bus);
    return found;
}

// The filters as the FileChooser's OpenFile takes them: a(sa(us)), 0 marking a glob.
GVariant* portalFilters(const std::vector<FileFilter>& filters) {
    GVariantBuilder list;
    g_variant_builder_init(&list, G_VARIANT_TYPE("a(sa(us))"));
    for (const FileFilter& filter : filters) {
        GVariantBuilder patterns;
        g_variant_builder_init(&patterns, G_VARIANT_TYPE("a(us)"));
        for (const std::string& p : filter.patterns)
            g_variant_builder_add(&patterns, "(us)", 0u, p.c_str());
        g_variant_builder_add(&list, "(sa(us))", filter.name.c_str(), &patterns);
    }
    return g_variant_builder_end(&list);
}

struct Waiting {
    GMainLoop* loop;
    std::optional<ChooserResult> answer;
};

void answered(GObject* source, GAsyncResult* result, gpointer data) {
    Waiting& waiting = *static_cast<Waiting*>(data);
    GError* error = nullptr;
    GVariant* reply = xdp_portal_open_file_finish(XDP_PORTAL(source), result, &error);
    if (!reply) {
        // The user's Cancel, or our own when the viewer quits; any other error is a portal
        // that could not show its dialog (no FileChooser backend): zenity may.
        const bool cancelled = g_error_matches(error, G_IO_ERROR, G_IO_ERROR_CANCELLED);
        waiting.answer = cancelled ? ChooserResult{ChooserResult::Kind::Cancelled, "", "portal"}
                                   : ChooserResult{ChooserResult::Kind::Unavailable, "",
                                                   std::string("portal: ") + error->message};
        g_clear_error(&error);
    } else {
        const char** uris = nullptr;
        if (g_variant_lookup(reply, "uris", "^a&s", &uris) && uris && uris[0])
            if (char* path = g_filename_from_uri(uris[0], nullptr, nullptr)) {
                waiting.answer = ChooserResult{ChooserResult::Kind::Chosen, path, "portal"};
                g_free(path);
            }
        g_free(uris);
        if (!waiting.answer)
            waiting.answer = ChooserResult{ChooserResult::Kind::Cancelled, "", "portal"};
        g_variant_unref(reply);
    }
    g_main_loop_quit(waiting.loop);
}

} // namespace

std::optional<ChooserResult> askPortal(const std::string& title,
                                       const std::vector<FileFilter>& filters,
                                       const std::function<void(std::function<void()>)>& onCancel) {
    if (!portalReachable()) return std::nullopt;
    // This thread's own context: libportal's callbacks are dispatched to it, not to a
    // default main loop that nobody runs.
    GMainContext* context = g_main_context_new();
    g_main_context_push_thread_default(context);
    Waiting waiting{g_main_loop_new(context, FALSE), std::nullopt};
    XdpPortal* portal = xdp_portal_new();
    GCancellable* cancel = g_cancellable_new();
    onCancel([cancel] { g_cancellable_cancel(cancel); }); // thread-safe in GIO
    xdp_portal_open_file(portal, nullptr, title.c_str(), portalFilters(filters), nullptr, nullptr,
                         XDP_OPEN_FILE_FLAG_NONE, cancel, answered, &waiting);
    g_main_loop_run(waiting.loop);
    onCancel(nullptr);
    g_object_unref(cancel);
    g_object_unref(portal);
    g_main_loop_unref(waiting.loop);
    g_main_context_pop_thread_default(context);
    g_main_context_unref(context);
    return waiting.answer;
}

} // namespace app
