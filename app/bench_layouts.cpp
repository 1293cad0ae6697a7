// The outer loop of bench over G-buffer layouts.
#include "bench_layouts.h"

#include "cli_values.h"
#include "core/gbuffer_layout.h"
#include "core/msaa.h"
#include "core/pipeline_fields.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace gbl {

namespace {

std::string layoutNames() {
    return fieldValuesText(*findPipelineField("layout"));
}

// The layout's multisampled targets at the measured size, at each sample count (docs/msaa.md).
void printMsaaMemory(GBufferLayoutDesc const& d, std::string const& size) {
    std::string error;
    if (auto const s = parseSize(size, &error)) std::printf("%s\n", msaaMemoryLine(d, s->width, s->height).c_str());
}

}  // namespace

int runBenchLayouts(BenchOptions const& o) {
    if (o.layouts.size() <= 1) {
        if (!o.layouts.empty() && !enumFromName<GBufferLayout>(kGBufferLayoutNames, o.layouts.front()))
            return benchBadArgument("--layouts: '" + o.layouts.front() + "' is not " + layoutNames());
        if (!o.layouts.empty())
            printMsaaMemory(layoutDesc(*enumFromName<GBufferLayout>(kGBufferLayoutNames, o.layouts.front())), o.size);
        return runBench(o);
    }
    for (auto const& name : o.layouts)
        if (!enumFromName<GBufferLayout>(kGBufferLayoutNames, name))
            return benchBadArgument("--layouts: '" + name + "' is not " + layoutNames());
    for (auto const& name : o.layouts) {
        GBufferLayoutDesc const& d = layoutDesc(*enumFromName<GBufferLayout>(kGBufferLayoutNames, name));
        std::printf("\n== G-buffer layout %s: %d bytes per pixel (", d.name.data(), layoutBytesPerPixel(d));
        for (std::size_t i = 0; i < d.attachments().size(); ++i)
            std::printf("%s%s %s %d", i ? ", " : "", d.attachments()[i].name.data(),
                        texelFormatName(d.attachments()[i].format).data(), texelBytes(d.attachments()[i].format));
        std::printf(") ==\n");
        printMsaaMemory(d, o.size);
        std::fflush(stdout);
        BenchOptions one = o;
        one.layouts = {name};
        if (o.jsonPath) {
            // One file per layout next to the one asked for: results_packed.json, ...
            std::filesystem::path p(*o.jsonPath);
            one.jsonPath = (p.parent_path() / (p.stem().string() + "_" + name + p.extension().string())).string();
        }
        if (int const rc = runBench(one); rc != 0) return rc;
    }
    return 0;
}

}  // namespace gbl
