// UI script commands for sessions, undo, crash recovery and export.
#include "script/script_run.h"

namespace gbl::ui {

namespace {

// An error sentence from the host: the check passes when there is none.
void expectOk(CommandCall const& c, std::optional<std::string> const& error) {
    c.check(!error, error.value_or(""));
}

void exportViewerCommand(CommandCall const& c) {
    if (!c.host.exportViewer) return c.check(false, "no export in this editor build");
    int viewer = -1;
    for (std::size_t i = 0; i < kViewerNames.size(); ++i)
        if (kViewerNames[i] == c.w[1]) viewer = int(i);
    if (viewer < 0 || (c.w[2] != "png" && c.w[2] != "exr"))
        return c.check(false, "expected a viewer name and png or exr");
    expectOk(c, c.host.exportViewer(viewer, c.w[2] == "exr", c.w[3]));
}

constexpr auto kSession = CommandNeeds::Session;

constexpr ScriptCommandSpec kSessionCommands[] = {
    {"save-session", "FILE", "File > Save as (the check fails when saving fails)",
     [](CommandCall const& c) { expectOk(c, c.host.saveSession(c.w[1])); }, kSession},
    {"open-session", "FILE", "File > Open; fails the check when the file is refused",
     [](CommandCall const& c) { expectOk(c, c.host.openSession(c.w[1])); }, kSession},
    {"open-bad-session", "FILE", "File > Open of a file that must be refused (editor keeps its state)",
     [](CommandCall const& c) {
         auto const error = c.host.openSession(c.w[1]);
         c.check(bool(error), error ? "refused: " + *error : "the file was accepted");
     },
     kSession},
    {"undo", "", "Ctrl+Z", [](CommandCall const& c) { c.host.undo(); }, kSession},
    {"redo", "", "Ctrl+Y", [](CommandCall const& c) { c.host.redo(); }, kSession},
    {"expect-recovery-offered", "", "a previous run's autosave is offered (after an unclean exit)",
     [](CommandCall const& c) { c.check(c.host.recoveryOffered(), ""); }, kSession},
    {"recover", "", "accept that offer", [](CommandCall const& c) { c.host.acceptRecovery(); }, kSession},
    {"wait-autosave", "SECONDS", "run frames until the editor wrote its recovery autosave (fails after SECONDS)",
     [](CommandCall const& c) {
         if (!c.host.autosaves) return c.check(false, "this editor run has no autosave (set GBL_RECOVERY_DIR)");
         int const before = c.host.autosaves();
         ScriptHost* host = &c.host;
         c.waitUntil([host, before] { return host->autosaves() > before; }, number(c.w[1]));
     }},
    {"export-all", "DIR", "File > Export all into DIR (the set `render --out` writes)",
     [](CommandCall const& c) {
         if (!c.host.exportAll) return c.check(false, "no export in this editor build");
         expectOk(c, c.host.exportAll(c.w[1]));
     }},
    {"export-viewer", "NAME png|exr FILE", "export a G-buffer viewer (position normal albedo specular depth)",
     exportViewerCommand},
};

}  // namespace

std::span<ScriptCommandSpec const> sessionCommands() {
    return kSessionCommands;
}

}  // namespace gbl::ui
