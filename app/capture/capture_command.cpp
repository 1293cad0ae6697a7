// The capture command: trace (or take a trace), find the passes, dump their state, write the manifest.
#include "capture/capture_command.h"

#include "capture/capture_mapping.h"
#include "capture/run_process.h"
#include "capture/state_dump.h"
#include "capture/trace_scan.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <future>

namespace gbl {

namespace fs = std::filesystem;
using namespace capture;

void addCaptureOptions(CLI::App& sub, CaptureOptions& o) {
    sub.add_option("--frame", o.frame, "The frame to capture, counted from 0 as apitrace counts them")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    sub.add_option("--out", o.outDir, "Directory for the manifest, its images and the lighting shader")
        ->capture_default_str();
    sub.add_option("--trace", o.trace, "Read this apitrace trace instead of running a program");
    sub.add_option("--api", o.api, "What the program draws through: egl or glx (auto: egl without a DISPLAY, else glx)")
        ->capture_default_str();
    sub.add_option("--timeout", o.timeout, "Seconds to wait for the frame before stopping the program")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    sub.add_flag("--open", o.open, "Open the result in the editor (as --gbuffer)");
    sub.add_flag("--time", o.time, "Print the seconds each step took (stderr)");
    sub.add_option("program", o.program, "-- PROGRAM [ARGS...]: the program to run under apitrace");
    sub.positionals_at_end();
}

namespace {

// SIGTERM or SIGINT while the program runs (the editor's Cancel, Ctrl+C): the traced program is stopped
// with apitrace, and nothing more is done.
std::atomic<bool> stopRequested{false};
extern "C" void onStopSignal(int) {
    stopRequested.store(true);
}

int refuse(std::string const& message) {
    std::fprintf(stderr, "gbuffer-lab capture: %s\n", message.c_str());
    return 2;
}

// The number of frames a (possibly still growing) trace holds so far.
int framesSoFar(std::string const& apitrace, std::string const& trace) {
    std::string error;
    auto const out = runForOutput({apitrace, "dump", "--grep=SwapBuffers", "--call-nos=no", trace}, &error);
    if (!out) return 0;
    int n = 0;
    for (std::size_t p = out->find("SwapBuffers"); p != std::string::npos; p = out->find("SwapBuffers", p + 1)) ++n;
    return n;
}

}  // namespace

int runCapture(CaptureOptions const& o, char const* self) {
    auto const start = std::chrono::steady_clock::now();
    auto lap = start;
    std::string times;
    auto step = [&](char const* name) {
        auto const now = std::chrono::steady_clock::now();
        char buf[64];
        std::snprintf(buf, sizeof buf, "%s%s %.2f s", times.empty() ? "" : ", ", name,
                      std::chrono::duration<double>(now - lap).count());
        times += buf;
        lap = now;
    };
    if (o.program.empty() == o.trace.empty())
        return refuse(o.trace.empty() ? "name a program after -- (capture -- ./my_renderer) or a trace with --trace"
                                      : "give either --trace FILE or a program after --, not both");
    auto const apitrace = findProgram("apitrace");
    if (!apitrace)
        return refuse("apitrace is not installed: install the Debian packages apitrace and apitrace-tracers");
    std::string error;
    std::error_code ec;
    fs::create_directories(o.outDir, ec);
    if (ec || !fs::is_directory(o.outDir)) return refuse("cannot create the folder " + o.outDir);

    std::string trace = o.trace;
    if (!o.trace.empty()) {
        if (!fs::is_regular_file(trace, ec)) return refuse(trace + " is not a file");
    } else {
        std::string const api = o.api == "auto" ? (std::getenv("DISPLAY") ? "glx" : "egl") : o.api;
        if (api != "egl" && api != "glx") return refuse("--api must be egl, glx or auto, got '" + o.api + "'");
        if (!findProgram(o.program[0])) return refuse(o.program[0] + " is not a program that can be run");
        trace = (fs::path(o.outDir) / "capture.trace").string();
        fs::remove(trace, ec);
        std::vector<std::string> argv{*apitrace, "trace", "--api", api == "glx" ? "gl" : "egl", "-o", trace};
        argv.insert(argv.end(), o.program.begin(), o.program.end());
        ProcessOptions po;
        po.stdoutPath = (fs::path(o.outDir) / "program.log").string();
        po.stderrPath = po.stdoutPath + ".err";
        po.timeoutSeconds = o.timeout;
        // Frame N is drawn once the trace holds N + 1 swaps; the writer flushes in chunks, so this is
        // seen a little late, never early.
        auto lastPoll = std::chrono::steady_clock::now();
        std::signal(SIGTERM, onStopSignal);
        std::signal(SIGINT, onStopSignal);
        po.shouldStop = [&] {
            if (stopRequested.load()) return true;
            auto const now = std::chrono::steady_clock::now();
            if (now - lastPoll < std::chrono::milliseconds(500)) return false;
            lastPoll = now;
            return fs::exists(trace) && framesSoFar(*apitrace, trace) > o.frame;
        };
        ProcessResult const r = runProcess(argv, po);
        if (!r.started) return refuse("apitrace could not be started (" + r.error + ")");
        if (stopRequested.load()) return refuse("stopped before frame " + std::to_string(o.frame) + " was captured");
        if (!fs::exists(trace) || fs::file_size(trace, ec) < 64)
            return refuse(o.program[0] + " exited (code " + std::to_string(r.exitCode) +
                          ") before drawing anything through " + api + ": see " + po.stderrPath);
    }

    step("trace");
    auto const info = runForOutput({*apitrace, "info", trace}, &error);
    if (!info) return refuse(trace + " is not an apitrace trace (" + error + ")");
    nlohmann::json const j = nlohmann::json::parse(*info, nullptr, false);
    std::string const apiName = j.is_object() ? j.value("API", "") : "";
    if (apiName.find("OpenGL") == std::string::npos)
        return refuse(trace + " records " + (apiName.empty() ? "an unknown API" : apiName) +
                      ", not OpenGL: capture reads OpenGL traces only");

    auto const listing =
        runForOutput({*apitrace, "dump", "--multiline=no", std::string("--grep=") + kScanCallsRegex, trace}, &error);
    if (!listing) return refuse("the trace could not be listed (" + error + ")");
    TraceScan const scan = scanTrace(*listing, o.frame);
    if (!scan.lightingDraw) return refuse(scan.error);
    step("find");

    bool const egl = listing->find("eglSwapBuffers") != std::string::npos;
    auto const retracer = findProgram(egl ? "eglretrace" : "glretrace");
    if (!retracer)
        return refuse(std::string(egl ? "eglretrace" : "glretrace") +
                      " is not installed: install the Debian package apitrace-tracers");
    // The two replays are independent: run them side by side.
    std::string geometryError, lightingError;
    auto geometryJob = std::async(std::launch::async,
                                  [&] { return dumpState(*retracer, trace, *scan.lastGeometryDraw, &geometryError); });
    auto lighting = dumpState(*retracer, trace, *scan.lightingDraw, &lightingError);
    auto geometry = geometryJob.get();
    if (!geometry) return refuse("the geometry draw's state could not be dumped: " + geometryError);
    if (!lighting) return refuse("the lighting draw's state could not be dumped: " + lightingError);
    step("dump");

    // The manifest names the trace beside it by its file name, another by its full path.
    std::string const traceName = fs::path(trace).parent_path() == fs::path(o.outDir)
                                      ? fs::path(trace).filename().string()
                                      : fs::absolute(trace, ec).string();
    auto const result = writeCapture(scan, *geometry, *lighting, {traceName, o.frame}, o.outDir, &error);
    if (!result) return refuse(error);
    step("write");
    if (o.time) std::fprintf(stderr, "capture: %s\n", times.c_str());
    double const seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: frame %d, G-buffer pass to call %llu, lighting pass at call %llu (%.2f s)\n",
                result->manifestPath.c_str(), o.frame, static_cast<unsigned long long>(*scan.lastGeometryDraw),
                static_cast<unsigned long long>(*scan.lightingDraw), seconds);
    if (!result->unmapped.empty()) std::printf("%s\n", result->unmapped.c_str());
    if (o.open) {
        std::fflush(stdout);
        std::string const manifest = result->manifestPath;
        // This very executable, whatever PATH or folder it was started from.
        ::execl("/proc/self/exe", self, "--gbuffer", manifest.c_str(), static_cast<char*>(nullptr));
        return refuse("the editor could not be started");
    }
    return 0;
}

}  // namespace gbl
