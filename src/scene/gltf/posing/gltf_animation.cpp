// Animation channels and samplers checked and sampled (glTF 2.0 section 3.11). tinygltf parses
// the indices and strings; nothing else about them is trusted.
#include "scene/gltf/posing/gltf_animation.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>

#include "scene/animation/keyframes.h"

namespace wf::gltf {

std::size_t morphTargetCount(const tinygltf::Model& model, int mesh) {
    std::size_t count = 0;
    for (const tinygltf::Primitive& p : model.meshes[mesh].primitives)
        count = std::max(count, p.targets.size());
    return count;
}

namespace {

std::vector<bool> chooseAnimations(const tinygltf::Model& model, const std::string& file,
                                   const std::string& which) {
    const std::size_t n = model.animations.size();
    std::vector<bool> chosen(n, which.empty());
    if (which.empty())
        return chosen;
    for (std::size_t a = 0; a < n; ++a)
        if (model.animations[a].name == which)
            chosen[a] = true;
    const bool digits = which.find_first_not_of("0123456789") == std::string::npos;
    if (digits && which.size() < 9 && std::stoul(which) < n &&
        std::find(chosen.begin(), chosen.end(), true) == chosen.end())
        chosen[std::stoul(which)] = true;
    if (std::find(chosen.begin(), chosen.end(), true) == chosen.end()) {
        std::string names;
        for (std::size_t a = 0; a < n; ++a)
            names += (a ? ", " : "") + std::to_string(a) +
                     (model.animations[a].name.empty() ? "" : " '" + model.animations[a].name + "'");
        fail(file, "--animation " + which + ": no such animation (the file has " +
                       (n == 0 ? std::string("none") : names) + ")");
    }
    return chosen;
}

// Which component types each path's output may have (glTF 2.0, table of animation outputs).
unsigned outputTypes(const std::string& path) {
    if (path == "rotation" || path == "weights")
        return FLOAT_BIT | BYTE_BIT | UBYTE_BIT | SHORT_BIT | USHORT_BIT; // ints normalized
    return FLOAT_BIT;
}

// Reads and checks one sampler for a channel of `width` values per key. With `unordered`, key
// times that do not increase are said there (and no keys returned) instead of refused.
anim::Keyframes readSampler(const tinygltf::Model& model, const std::string& file,
                            AccessorReader& reader, const tinygltf::AnimationSampler& sampler,
                            const std::string& name, const std::string& path, std::size_t width,
                            std::string* unordered) {
    anim::Keyframes keys;
    keys.width = width;
    keys.rotation = path == "rotation";
    if (sampler.interpolation == "LINEAR")
        keys.interpolation = anim::Interpolation::Linear;
    else if (sampler.interpolation == "STEP")
        keys.interpolation = anim::Interpolation::Step;
    else if (sampler.interpolation == "CUBICSPLINE")
        keys.interpolation = anim::Interpolation::CubicSpline;
    else
        fail(file, name + ": interpolation '" + sampler.interpolation +
                       "' is not LINEAR, STEP or CUBICSPLINE");
    checkIndex(file, sampler.input, model.accessors.size(), "input accessor", name);
    checkIndex(file, sampler.output, model.accessors.size(), "output accessor", name);
    const tinygltf::Accessor& input = model.accessors[sampler.input];
    if (input.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || input.type != TINYGLTF_TYPE_SCALAR)
        fail(file, name + ": input accessor " + std::to_string(sampler.input) +
                       " must hold float scalars (key times)");
    const FloatArray& times = reader.floats(sampler.input, "key times of " + name, 1);
    if (times.count == 0)
        fail(file, name + ": no key times");
    for (std::size_t k = 0; k < times.count; ++k) {
        if (times.values[k] < 0.0f || (k > 0 && !(times.values[k] > times.values[k - 1]))) {
            const std::string problem = name + ": key time " + std::to_string(k) +
                                        " is negative or not after the one before (times must "
                                        "increase)";
            if (!unordered)
                fail(file, problem);
            *unordered = problem;
            return keys;
        }
    }
    const bool cubic = keys.interpolation == anim::Interpolation::CubicSpline;
    if (cubic && times.count < 2)
        fail(file, name + ": CUBICSPLINE needs at least two keys");
    const tinygltf::Accessor& output = model.accessors[sampler.output];
    const unsigned allowed = outputTypes(path);
    const int bit = output.componentType - TINYGLTF_COMPONENT_TYPE_BYTE;
    const bool isFloat = output.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    if (bit < 0 || bit > 6 || !(allowed & (1u << bit)) || (!isFloat && !output.normalized))
        fail(file, name + ": output accessor " + std::to_string(sampler.output) + " of " + path +
                       " must hold floats" +
                       (allowed == FLOAT_BIT ? "" : " or normalized 8/16-bit integers"));
    const int components = path == "weights" ? 1 : keys.rotation ? 4 : 3;
    const FloatArray& values = reader.floats(sampler.output, path + " of " + name, components);
    const std::size_t expected = times.count * (cubic ? 3 : 1) * (path == "weights" ? width : 1);
    if (values.count != expected)
        fail(file, name + ": output has " + std::to_string(values.count) + " elements, but " +
                       std::to_string(times.count) + " keys of " + sampler.interpolation +
                       (path == "weights" ? " for " + std::to_string(width) + " morph targets" : "") +
                       " need " + std::to_string(expected));
    keys.times = times.values;
    keys.values = values.values;
    return keys;
}

} // namespace

std::vector<NodeAnimation> sampleAnimations(const tinygltf::Model& model, const std::string& file,
                                            AccessorReader& reader, double time,
                                            const std::string& which, double* lastKey,
                                            bool restPoseOnBadKeys) {
    std::vector<NodeAnimation> nodes(model.nodes.size());
    if (lastKey)
        *lastKey = 0.0;
    const std::vector<bool> chosen = chooseAnimations(model, file, which);
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& animation = model.animations[a];
        const std::string aname = "animation " + std::to_string(a);
        if (animation.channels.empty())
            fail(file, aname + " has no channels");
        // This animation's channels, applied once all of them read well: an animation dropped
        // for its key times leaves no channel behind.
        struct Write {
            int node;
            const std::string* path;
            std::vector<double> value;
        };
        std::vector<Write> writes;
        double animationLastKey = 0.0;
        bool dropped = false;
        for (std::size_t c = 0; c < animation.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = animation.channels[c];
            const std::string cname = aname + " channel " + std::to_string(c);
            if (channel.sampler < 0 || std::size_t(channel.sampler) >= animation.samplers.size())
                fail(file, cname + ": sampler " + std::to_string(channel.sampler) +
                               " does not exist (the animation has " +
                               std::to_string(animation.samplers.size()) + ")");
            const std::string& path = channel.target_path;
            if (path != "translation" && path != "rotation" && path != "scale" &&
                path != "weights")
                fail(file, cname + ": target path '" + path +
                               "' is not translation, rotation, scale or weights");
            if (channel.target_node == -1)
                continue; // glTF: a channel without a node (extensions may target others)
            checkIndex(file, channel.target_node, model.nodes.size(), "target node", cname);
            const tinygltf::Node& node = model.nodes[channel.target_node];
            const std::string nodeName = "node " + std::to_string(channel.target_node);
            if (!node.matrix.empty() && path != "weights")
                fail(file, cname + " animates the " + path + " of " + nodeName +
                               ", which has a matrix (glTF: animated nodes use TRS)");
            std::size_t width = path == "rotation" ? 4 : 3;
            if (path == "weights") {
                width = node.mesh >= 0 && std::size_t(node.mesh) < model.meshes.size()
                            ? morphTargetCount(model, node.mesh)
                            : 0;
                if (width == 0)
                    fail(file, cname + " animates the weights of " + nodeName +
                                   ", which has no mesh with morph targets");
            }
            const std::string sname =
                aname + " sampler " + std::to_string(channel.sampler) + " (" + cname + ")";
            std::string unordered;
            const anim::Keyframes keys =
                readSampler(model, file, reader, animation.samplers[channel.sampler], sname, path,
                            width, restPoseOnBadKeys ? &unordered : nullptr);
            if (!unordered.empty()) {
                warn(file, aname + " ignored (the scene is rendered at time 0 without it; a "
                               "--time or --animation asking for it refuses the file): " +
                               unordered);
                dropped = true;
                break;
            }
            if (!chosen[a])
                continue;
            animationLastKey = std::max(animationLastKey, double(keys.times.back()));
            writes.push_back({channel.target_node, &path, anim::sample(keys, time)});
        }
        if (dropped)
            continue;
        if (lastKey)
            *lastKey = std::max(*lastKey, animationLastKey);
        for (const Write& write : writes) {
            const std::vector<double>& v = write.value;
            NodeAnimation& target = nodes[write.node];
            if (*write.path == "translation")
                target.translation = glm::dvec3(v[0], v[1], v[2]);
            else if (*write.path == "scale")
                target.scale = glm::dvec3(v[0], v[1], v[2]);
            else if (*write.path == "rotation")
                target.rotation = glm::dquat(v[3], v[0], v[1], v[2]);
            else
                target.weights = v;
        }
    }
    return nodes;
}

} // namespace wf::gltf
