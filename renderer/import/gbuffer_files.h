// Reading one attachment file into floats: raw samples, or an image through image/image_io.h,
// decoding only the channels the manifest names. Internal to gbl_import.
#pragma once

#include "import/gbuffer_manifest.h"
#include "import/imported_gbuffer.h"

#include <optional>
#include <string>
#include <vector>

namespace gbl::detail {

struct FileImage {
    int width = 0;
    int height = 0;
    int channels = 0;  // decoded: the file's channels [firstChannel, firstChannel + channels)
    int firstChannel = 0;
    int fileChannels = 0;  // all the file has
    SampleStorage storage = SampleStorage::Float;
    std::vector<float> pixels;
};

// The channels the manifest reads of one file, as the range [first, last] to decode.
struct ChannelRange {
    int first = 0, last = -1;
};

std::string sizeText(int w, int h);

// The file `ref` names, its channels range.first..range.last decoded (all of them for raw files and in
// the browser); nullopt with one sentence naming the field when it cannot be read.
std::optional<FileImage> readFile(ImageRef const& ref, ChannelRange range, std::string* error);

}  // namespace gbl::detail
