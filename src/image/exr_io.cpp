// EXR through OpenEXR's C++ API. Pixels are handed over as one interleaved RGB array: the
// slices point into it with a 12-byte x stride, so no per-channel copies are made.
#include "image/exr_io.h"

#include <ImfChannelList.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>

#include "errors.h"
#include "image/atomic_file.h"

namespace wf {
namespace {

// Larger images are almost certainly a corrupt header; refusing them before allocating keeps
// a bad file from asking for terabytes.
constexpr int64_t MAX_EXR_SIDE = 32768;
constexpr const char* CHANNELS[3] = {"R", "G", "B"};

Imf::Slice rgbSlice(const float* base, int channel, const Imath::Box2i& window, int width) {
    const size_t xStride = 3 * sizeof(float);
    return Imf::Slice::Make(Imf::FLOAT, base + channel, window, xStride,
                            xStride * static_cast<size_t>(width));
}

} // namespace

void writeExr(const std::string& path, int width, int height, const std::vector<float>& rgb,
              const std::vector<std::pair<std::string, std::string>>& stringAttrs,
              const std::vector<std::pair<std::string, float>>& floatAttrs,
              const std::vector<std::pair<std::string, int>>& intAttrs,
              const std::vector<ExrChannel>& extraChannels) {
    const size_t pixels = static_cast<size_t>(std::max(width, 0)) * std::max(height, 0);
    for (const ExrChannel& channel : extraChannels)
        if (channel.values.size() != pixels)
            throw InternalError("writeExr(" + path + "): channel " + channel.name + " has " +
                                std::to_string(channel.values.size()) + " values for " +
                                std::to_string(pixels) + " pixels");
    if (width <= 0 || height <= 0 ||
        rgb.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 3) {
        throw InternalError("writeExr(" + path + "): " + std::to_string(width) + "x" +
                            std::to_string(height) + " image with " +
                            std::to_string(rgb.size()) + " floats");
    }
    Imf::Header header(width, height);
    try {
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const char* name : CHANNELS) {
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        }
        for (const ExrChannel& channel : extraChannels)
            header.channels().insert(channel.name, Imf::Channel(Imf::FLOAT));
        // OpenEXR throws here when a name is empty or a standard attribute of another type.
        for (const auto& [name, value] : stringAttrs) {
            header.insert(name, Imf::StringAttribute(value));
        }
        for (const auto& [name, value] : floatAttrs) {
            header.insert(name, Imf::FloatAttribute(value));
        }
        for (const auto& [name, value] : intAttrs) {
            header.insert(name, Imf::IntAttribute(value));
        }
    } catch (const std::exception& e) {
        throw InternalError("cannot write " + path + ": " + e.what());
    }

    writeFileAtomically(path, [&](const std::string& tmpPath) {
        try {
            Imf::OutputFile file(tmpPath.c_str(), header);
            Imf::FrameBuffer frame;
            for (int c = 0; c < 3; ++c) {
                frame.insert(CHANNELS[c], rgbSlice(rgb.data(), c, header.dataWindow(), width));
            }
            for (const ExrChannel& channel : extraChannels)
                frame.insert(channel.name,
                             Imf::Slice::Make(Imf::FLOAT, channel.values.data(),
                                              header.dataWindow(), sizeof(float),
                                              sizeof(float) * static_cast<size_t>(width)));
            file.setFrameBuffer(frame);
            file.writePixels(height);
        } catch (const std::exception& e) {
            throw InternalError("cannot write " + path + ": " + e.what());
        }
    });
}

ExrImage readExr(const std::string& path) {
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const int64_t width = int64_t(window.max.x) - window.min.x + 1;
        const int64_t height = int64_t(window.max.y) - window.min.y + 1;
        if (width <= 0 || height <= 0 || width > MAX_EXR_SIDE || height > MAX_EXR_SIDE) {
            throw InputError(path + ": data window of " + std::to_string(width) + "x" +
                             std::to_string(height) + " pixels is empty or too large");
        }
        for (const char* name : CHANNELS) {
            if (!file.header().channels().findChannel(name)) {
                throw InputError(path + ": no channel " + name);
            }
        }
        ExrImage image;
        image.width = static_cast<int>(width);
        image.height = static_cast<int>(height);
        image.rgb.assign(static_cast<size_t>(width * height * 3), 0.0f);
        Imf::FrameBuffer frame;
        for (int c = 0; c < 3; ++c) {
            frame.insert(CHANNELS[c], rgbSlice(image.rgb.data(), c, window, image.width));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(path + ": cannot read EXR: " + e.what());
    }
}

std::optional<std::string> readExrAttribute(const std::string& path, const std::string& name) {
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        if (auto* s = header.findTypedAttribute<Imf::StringAttribute>(name)) {
            return s->value();
        }
        if (auto* i = header.findTypedAttribute<Imf::IntAttribute>(name)) {
            return std::to_string(i->value());
        }
        if (auto* f = header.findTypedAttribute<Imf::FloatAttribute>(name)) {
            char text[32];
            std::snprintf(text, sizeof(text), "%.9g", static_cast<double>(f->value()));
            return std::string(text);
        }
        return std::nullopt;
    } catch (const std::exception& e) {
        throw InputError(path + ": cannot read EXR: " + e.what());
    }
}

std::vector<ExrAttribute> readExrAttributes(const std::string& path) {
    std::vector<ExrAttribute> attributes;
    try {
        Imf::InputFile file(path.c_str());
        for (auto it = file.header().begin(); it != file.header().end(); ++it) {
            const Imf::Attribute& value = it.attribute();
            if (auto* s = dynamic_cast<const Imf::StringAttribute*>(&value)) {
                attributes.push_back({it.name(), 's', s->value()});
            } else if (auto* i = dynamic_cast<const Imf::IntAttribute*>(&value)) {
                attributes.push_back({it.name(), 'i', std::to_string(i->value())});
            } else if (auto* f = dynamic_cast<const Imf::FloatAttribute*>(&value)) {
                char text[32];
                std::snprintf(text, sizeof(text), "%.9g", static_cast<double>(f->value()));
                attributes.push_back({it.name(), 'f', text});
            }
        }
    } catch (const std::exception& e) {
        throw InputError(path + ": cannot read EXR: " + e.what());
    }
    return attributes;
}

std::optional<std::vector<float>> readExrChannel(const std::string& path, const std::string& name) {
    try {
        Imf::InputFile file(path.c_str());
        if (!file.header().channels().findChannel(name))
            return std::nullopt;
        const Imath::Box2i window = file.header().dataWindow();
        const int width = window.max.x - window.min.x + 1;
        const int height = window.max.y - window.min.y + 1;
        if (width <= 0 || height <= 0 || width > MAX_EXR_SIDE || height > MAX_EXR_SIDE)
            throw InputError(path + ": data window of " + std::to_string(width) + "x" +
                             std::to_string(height));
        std::vector<float> values(static_cast<size_t>(width) * height);
        Imf::FrameBuffer frame;
        frame.insert(name, Imf::Slice::Make(Imf::FLOAT, values.data(), window, sizeof(float),
                                            sizeof(float) * static_cast<size_t>(width)));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        return values;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(path + ": cannot read EXR: " + e.what());
    }
}

} // namespace wf
