// The constants C++ and GLSL share: the enum values view.frag switches on, the binding slots of
// shaders/bindings.glsl, and the program table's order.
#include "core/cluster_math.h"
#include "core/heat_scale.h"
#include "core/pipeline_settings.h"
#include "core/point_light.h"
#include "core/view_params.h"
#include "gl/program_id.h"
#include "gl/shader_bindings.h"

#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace gbl;

namespace {

// Every `#define NAME NUMBER` line of a shader file.
std::map<std::string, int> defines(std::string const& file) {
    std::ifstream f(std::string(GBL_SOURCE_DIR) + "/shaders/" + file);
    EXPECT_TRUE(f) << "cannot read shaders/" << file;
    std::map<std::string, int> out;
    std::regex const line(R"(^#define ([A-Z0-9_]+) +([0-9]+)\b.*)");
    std::string text;
    while (std::getline(f, text)) {
        std::smatch m;
        if (std::regex_match(text, m, line)) out[m[1]] = std::stoi(m[2]);
    }
    return out;
}

// The numbers of a `const TYPE NAME... = ...;` line of a shader file (names and type words
// dropped), in order; empty when no such line exists.
std::vector<double> constNumbers(std::string const& file, std::string const& name) {
    std::ifstream f(std::string(GBL_SOURCE_DIR) + "/shaders/" + file);
    EXPECT_TRUE(f) << "cannot read shaders/" << file;
    std::stringstream ss;
    ss << f.rdbuf();
    std::string const text = ss.str();
    std::smatch m;
    if (!std::regex_search(text, m, std::regex("\\bconst [a-z0-9]+ " + name + "\\b"))) return {};
    std::size_t const start = std::size_t(m.position(0));
    std::size_t const eq = text.find('=', start), end = text.find(';', start);
    std::string const words =
        std::regex_replace(text.substr(eq + 1, end - eq - 1), std::regex("[A-Za-z_][A-Za-z_0-9]*"), " ");
    std::vector<double> out;
    std::regex const number(R"(-?[0-9]+(\.[0-9]+)?)");
    for (std::sregex_iterator it(words.begin(), words.end(), number), e; it != e; ++it)
        out.push_back(std::stod(it->str()));
    return out;
}

std::string upper(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = char(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

// The defines with `prefix` match the names list one-to-one, value = enum index.
template <std::size_t N>
void expectMatchesEnum(std::map<std::string, int> const& all, std::string const& prefix,
                       std::array<std::string_view, N> const& names) {
    int found = 0;
    for (auto const& [name, value] : all)
        if (name.rfind(prefix, 0) == 0) ++found;
    EXPECT_EQ(found, int(N)) << prefix << "* defines in view_constants.glsl vs C++ enum values";
    for (std::size_t i = 0; i < N; ++i) {
        auto const it = all.find(prefix + upper(names[i]));
        ASSERT_NE(it, all.end()) << prefix + upper(names[i]) << " is missing from shaders/view_constants.glsl";
        EXPECT_EQ(it->second, int(i)) << it->first;
    }
}

}  // namespace

TEST(ShaderConstants, ViewConstantsMatchTheEnums) {
    auto const all = defines("view_constants.glsl");
    expectMatchesEnum(all, "VIEW_", kDebugViewNames);
    expectMatchesEnum(all, "TONEMAP_", kTonemapNames);
    ASSERT_EQ(all.count("NORMALS_BIASED"), 1u);
    ASSERT_EQ(all.count("NORMALS_ABSOLUTE"), 1u);
    EXPECT_EQ(all.at("NORMALS_BIASED"), int(NormalDisplay::Biased));
    EXPECT_EQ(all.at("NORMALS_ABSOLUTE"), int(NormalDisplay::Absolute));
    expectMatchesEnum(all, "COLORMAP_", kColormapNames);
    std::map<std::string, int> overlays;
    for (auto const& [name, value] : all)
        if (name.rfind("OVERLAY_", 0) == 0) overlays[name] = value;
    std::map<std::string, int> const cpp{{"OVERLAY_NAN", int(kOverlayNaN)},
                                         {"OVERLAY_INF", int(kOverlayInf)},
                                         {"OVERLAY_NEGATIVE", int(kOverlayNegative)},
                                         {"OVERLAY_CLIP", int(kOverlayClip)}};
    EXPECT_EQ(overlays, cpp);
    ASSERT_EQ(all.count("SLICE_SWATCH"), 1u);
    EXPECT_EQ(all.at("SLICE_SWATCH"), kSliceSwatchTexels);
}

TEST(ShaderConstants, HeatScaleMatchesTheShader) {
    // The heat maps' bins and colours (core/heat_scale.h) are the ones view.frag draws.
    auto const all = defines("view_constants.glsl");
    ASSERT_EQ(all.count("HEAT_BINS"), 1u);
    EXPECT_EQ(all.at("HEAT_BINS"), kHeatBins);
    ASSERT_EQ(all.count("HEAT_SWATCH"), 1u);
    EXPECT_EQ(all.at("HEAT_SWATCH"), kHeatSwatchTexels);
    std::vector<double> const edges = constNumbers("view_constants.glsl", "HEAT_EDGES");
    ASSERT_EQ(edges.size(), std::size_t(kHeatBins));
    for (int k = 0; k < kHeatBins; ++k) EXPECT_EQ(edges[std::size_t(k)], kHeatBinEdges[std::size_t(k)]) << k;
    std::vector<double> const colors = constNumbers("view_constants.glsl", "HEAT_COLORS");
    ASSERT_EQ(colors.size(), std::size_t(3 * kHeatBins));
    for (int k = 0; k < kHeatBins; ++k)
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(colors[std::size_t(3 * k + c)], kHeatBinColors[std::size_t(k)][std::size_t(c)])
                << "bin " << k << " channel " << c;
    std::vector<double> const dim = constNumbers("view_constants.glsl", "HEAT_WASTED_DIM");
    ASSERT_EQ(dim.size(), 1u);
    EXPECT_FLOAT_EQ(float(dim[0]), kHeatWastedDim);
}

TEST(ShaderConstants, DirectionalLightLimitMatchesTheShader) {
    auto const all = defines("light_fetch.glsl");
    ASSERT_EQ(all.count("MAX_DIRECTIONAL_LIGHTS"), 1u);
    EXPECT_EQ(all.at("MAX_DIRECTIONAL_LIGHTS"), kMaxDirectionalLights);
}

TEST(ShaderConstants, ViewShaderTakesItsConstantsFromTheSharedFile) {
    // A second copy of the values in view.frag would drift from the checked one.
    EXPECT_TRUE(defines("view.frag").empty());
    EXPECT_TRUE(defines("view_tools.glsl").empty());
    std::ifstream f(std::string(GBL_SOURCE_DIR) + "/shaders/view.frag");
    std::stringstream ss;
    ss << f.rdbuf();
    EXPECT_NE(ss.str().find("#include \"view_constants.glsl\""), std::string::npos);
}

TEST(ShaderConstants, GeneratedBindingsHeaderMatchesBindingsGlsl) {
    // The header is generated at configure time; an edit of bindings.glsl reconfigures. This
    // catches a stale build tree and a parse that dropped a line.
    auto const all = defines("bindings.glsl");
    std::map<std::string, int> const cpp{{"BIND_GBUFFER_POSITION", slot::BIND_GBUFFER_POSITION},
                                         {"BIND_GBUFFER_NORMAL", slot::BIND_GBUFFER_NORMAL},
                                         {"BIND_GBUFFER_ALBEDO_SPEC", slot::BIND_GBUFFER_ALBEDO_SPEC},
                                         {"BIND_LIGHTS", slot::BIND_LIGHTS},
                                         {"BIND_VOLUME_INSTANCES", slot::BIND_VOLUME_INSTANCES},
                                         {"BIND_DEPTH", slot::BIND_DEPTH},
                                         {"BIND_LIGHTING", slot::BIND_LIGHTING},
                                         {"BIND_COVERAGE", slot::BIND_COVERAGE},
                                         {"BIND_MATERIAL_BASE_COLOR", slot::BIND_MATERIAL_BASE_COLOR},
                                         {"BIND_MATERIAL_NORMAL", slot::BIND_MATERIAL_NORMAL},
                                         {"BIND_MATERIAL_SPECULAR", slot::BIND_MATERIAL_SPECULAR},
                                         {"BIND_GBUFFER_EMISSIVE", slot::BIND_GBUFFER_EMISSIVE},
                                         {"BIND_MATERIAL_EMISSIVE", slot::BIND_MATERIAL_EMISSIVE},
                                         {"BIND_MATERIAL_OCCLUSION", slot::BIND_MATERIAL_OCCLUSION},
                                         {"BIND_DIFFUSE_LIGHT", slot::BIND_DIFFUSE_LIGHT},
                                         {"BIND_SPECULAR_LIGHT", slot::BIND_SPECULAR_LIGHT},
                                         {"BIND_IMAGE_SPECULAR_LIGHT", slot::BIND_IMAGE_SPECULAR_LIGHT},
                                         {"BIND_IMAGE_LIGHTING", slot::BIND_IMAGE_LIGHTING},
                                         {"BIND_IMAGE_COVERAGE", slot::BIND_IMAGE_COVERAGE},
                                         {"BIND_SSBO_CLUSTER_COUNTS", slot::BIND_SSBO_CLUSTER_COUNTS},
                                         {"BIND_SSBO_CLUSTER_LIGHTS", slot::BIND_SSBO_CLUSTER_LIGHTS},
                                         {"BIND_SSBO_TILE_BIN_COUNTS", slot::BIND_SSBO_TILE_BIN_COUNTS},
                                         {"BIND_SSBO_TILE_BIN_LIGHTS", slot::BIND_SSBO_TILE_BIN_LIGHTS},
                                         {"BIND_SSBO_TILE_DEPTH", slot::BIND_SSBO_TILE_DEPTH},
                                         {"BIND_SSBO_SHADER_CHECKS", slot::BIND_SSBO_SHADER_CHECKS},
                                         {"BIND_CLUSTER_LIST", slot::BIND_CLUSTER_LIST},
                                         {"BIND_PREPASS_NORMAL", slot::BIND_PREPASS_NORMAL},
                                         {"BIND_READBACK_SOURCE", slot::BIND_READBACK_SOURCE},
                                         {"BIND_IMPORT_POSITION_DEPTH", slot::BIND_IMPORT_POSITION_DEPTH},
                                         {"BIND_IMPORT_NORMAL", slot::BIND_IMPORT_NORMAL},
                                         {"BIND_IMPORT_ALBEDO_SPEC", slot::BIND_IMPORT_ALBEDO_SPEC},
                                         {"BIND_IMPORT_EMISSIVE_AO", slot::BIND_IMPORT_EMISSIVE_AO}};
    EXPECT_EQ(all, cpp);
    // Each sampler uniform has exactly one unit, and the G-buffer samplers, the lights, every
    // texture the view pass reads and the combine pass's light targets are distinct (they are
    // bound together); so are the forward pass's material textures and the lights.
    std::set<std::string> names;
    for (auto const& s : slot::kSamplerSlots) EXPECT_TRUE(names.insert(s.uniform).second) << s.uniform;
    std::ifstream f(std::string(GBL_SOURCE_DIR) + "/shaders/bindings.glsl");
    std::size_t annotated = 0;
    for (std::string line; std::getline(f, line);)
        annotated += line.rfind("#define BIND_", 0) == 0 && line.find("// sampler ") != std::string::npos;
    EXPECT_EQ(names.size(), annotated) << "every `// sampler uName` annotation reaches kSamplerSlots";
    std::set<int> const together{
        slot::BIND_GBUFFER_POSITION, slot::BIND_GBUFFER_NORMAL,   slot::BIND_GBUFFER_ALBEDO_SPEC,
        slot::BIND_LIGHTS,           slot::BIND_VOLUME_INSTANCES, slot::BIND_DEPTH,
        slot::BIND_LIGHTING,         slot::BIND_COVERAGE,         slot::BIND_GBUFFER_EMISSIVE,
        slot::BIND_DIFFUSE_LIGHT,    slot::BIND_SPECULAR_LIGHT};
    EXPECT_EQ(together.size(), 11u);
    std::set<int> const forward{slot::BIND_MATERIAL_BASE_COLOR, slot::BIND_MATERIAL_NORMAL,
                                slot::BIND_MATERIAL_SPECULAR,   slot::BIND_MATERIAL_EMISSIVE,
                                slot::BIND_MATERIAL_OCCLUSION,  slot::BIND_LIGHTS};
    EXPECT_EQ(forward.size(), 6u);
    // The import pass binds its four textures together (passes/import.cpp).
    std::set<int> const imported{slot::BIND_IMPORT_POSITION_DEPTH, slot::BIND_IMPORT_NORMAL,
                                 slot::BIND_IMPORT_ALBEDO_SPEC, slot::BIND_IMPORT_EMISSIVE_AO};
    EXPECT_EQ(imported.size(), 4u);
    // GL 3.3 guarantees 16 texture units per fragment stage.
    for (auto const& s : slot::kSamplerSlots) EXPECT_LT(s.unit, 16) << s.uniform;
}

TEST(ShaderConstants, ProgramTableIsInIdOrderWithCoreFirst) {
    auto const table = programTable();
    ASSERT_EQ(table.size(), kProgramCount);
    std::set<std::string> names;
    for (std::size_t i = 0; i < table.size(); ++i) {
        EXPECT_EQ(std::size_t(table[i].id), i) << table[i].desc.name;
        EXPECT_TRUE(names.insert(table[i].desc.name).second) << "two programs named " << table[i].desc.name;
        EXPECT_FALSE(table[i].desc.stages.empty()) << table[i].desc.name;
    }
    // Only what the quad and forward modes need is fatal; the compute program never is.
    EXPECT_EQ(programInfo(ProgramId::LightingTiled).group, ProgramGroup::Tiled);
    EXPECT_EQ(programInfo(ProgramId::LightVolume).group, ProgramGroup::Volumes);
    EXPECT_EQ(programInfo(ProgramId::LightingQuad).group, ProgramGroup::Core);
    for (auto const& p : table)
        for (auto const& [stage, file] : p.desc.stages)
            if (stage == GL_COMPUTE_SHADER) {
                EXPECT_NE(p.group, ProgramGroup::Core) << p.desc.name;
            }
}
