// render --frames A..B[:STEP]: a sequence of frames from one process, each the scene posed at
// frame / --fps seconds and written to -o's pattern (printf's %d or %0Nd). The device, the
// shader compiler (and its SPIR-V) and the validation context are made once, and so is the
// renderer with its pipelines while the frames need the same shaders; each frame loads and
// poses the scene, refits the last built tree or builds one (render/gpu_scene/frame_scenes.h),
// uploads its tables and renders.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "app/cli.h"
#include "app/render_flags.h"

namespace wf {

// "A..B" or "A..B:STEP" (A <= B, STEP >= 1) as the frame numbers; UsageError otherwise.
std::vector<uint32_t> parseFrameRange(const std::string& text);

// The output path of a frame: `pattern` with its one %d or %0Nd (N <= 9) replaced by the
// frame; UsageError for a pattern with no such conversion, another conversion or two.
std::string framePath(const std::string& pattern, uint32_t frame);

// Renders every frame of --frames; returns the exit code. `request` is the render's flags
// (renderRequestFrom); flags that do not apply to a sequence were refused before.
int runFrameSequence(const ParsedArgs& parsed, const RenderRequest& request);

// UsageError for flags that make no sense with --frames (--time, --frame, --resume,
// --checkpoint, --target-error, --json).
void checkFrameFlags(const ParsedArgs& parsed);

} // namespace wf
