// The shader-checks report: reading the record compute shaders leave (shaders/shader_checks.glsl).
#include "gl/shader_checks.h"

#include "gl/program_id.h"
#include "gl/shader_bindings.h"

#include <atomic>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <sstream>

namespace gbl {

namespace {
std::atomic<std::uint64_t> gFailures{0};
std::mutex gReportMutex;
std::string gLastReport;
}  // namespace

bool shaderChecksRequested() {
    if (char const* env = std::getenv("GBL_SHADER_CHECKS"); env && *env) return std::string_view(env) != "0";
#ifdef GBL_SHADER_CHECKS_DEFAULT
    return true;
#else
    return false;
#endif
}

std::uint64_t shaderCheckFailureCount() {
    return gFailures.load();
}

std::string lastShaderCheckReport() {
    std::lock_guard lock(gReportMutex);
    return gLastReport;
}

// "#define CHECK_SITE_NAME N" lines, read by hand: GCC 12's <regex> at -O1 under the sanitizers warns
// (-Wmaybe-uninitialized inside its own std::function), which fails the -Werror sanitizer build.
std::vector<std::string> shaderCheckSiteNames(std::string_view checksSource) {
    std::vector<std::string> names;
    auto const space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    auto const nameChar = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; };
    std::string_view const define = "#define", prefix = "CHECK_SITE_";
    std::string_view const t = checksSource;
    for (std::size_t at = t.find(define); at != std::string_view::npos; at = t.find(define, at + 1)) {
        std::size_t p = at + define.size();
        std::size_t const gap = p;
        while (p < t.size() && space(t[p])) ++p;
        if (p == gap || t.substr(p, prefix.size()) != prefix) continue;
        p += prefix.size();
        std::size_t const nameBegin = p;
        while (p < t.size() && nameChar(t[p])) ++p;
        std::size_t const nameEnd = p;
        while (p < t.size() && space(t[p])) ++p;
        std::size_t const digits = p;
        while (p < t.size() && std::isdigit(static_cast<unsigned char>(t[p]))) ++p;
        if (nameEnd == nameBegin || digits == nameEnd || p == digits || p - digits > 9) continue;
        std::size_t const n = std::stoul(std::string(t.substr(digits, p - digits)));
        if (n > 1000) continue;  // not a site number
        if (names.size() <= n) names.resize(n + 1);
        std::string name(t.substr(nameBegin, nameEnd - nameBegin));
        for (char& c : name) c = c == '_' ? ' ' : char(std::tolower(static_cast<unsigned char>(c)));
        names[n] = name;
    }
    return names;
}

std::string describeShaderChecks(ShaderCheckRecord const& r, std::vector<std::string> const& siteNames) {
    std::ostringstream s;
    std::string const program =
        r.program < kProgramCount ? programInfo(ProgramId(r.program)).desc.name : "#" + std::to_string(r.program);
    std::string const site = r.site < siteNames.size() && !siteNames[r.site].empty() ? siteNames[r.site] : "an access";
    s << "shader check: " << r.failures << " out-of-range access" << (r.failures == 1 ? "" : "es")
      << " this frame; the first in program " << program << ", " << site << " (site " << r.site << "): index "
      << r.index << " outside [0, " << r.size << ")";
    return s.str();
}

ShaderChecks ShaderChecks::create(std::vector<std::string> siteNames) {
    ShaderChecks c;
    ShaderCheckRecord const zero{};
    c.buffer_ = gl::Buffer::create(GL_SHADER_STORAGE_BUFFER, sizeof zero, &zero, GL_DYNAMIC_COPY, "shader checks");
    c.siteNames_ = std::move(siteNames);
    return c;
}

void ShaderChecks::begin() {
    ShaderCheckRecord const zero{};
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer_.id());
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof zero, &zero);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_SHADER_CHECKS, buffer_.id());
}

std::optional<std::string> ShaderChecks::collect() {
    ShaderCheckRecord r{};
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer_.id());
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof r, &r);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    if (r.failures == 0) return std::nullopt;
    std::string report = describeShaderChecks(r, siteNames_);
    gFailures += r.failures;
    {
        std::lock_guard lock(gReportMutex);
        gLastReport = report;
    }
    std::fprintf(stderr, "%s\n", report.c_str());
    return report;
}

}  // namespace gbl
