// wavefront: subcommand dispatch and the mapping of failures to exit codes
// (0 done, 2 bad usage or bad input, 1 internal or device failure).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "app/commands.h"
#include "errors.h"

namespace {

const char* kTopHelp =
    "Usage: wavefront COMMAND [options]\n"
    "\n"
    "Wavefront renders glTF 2.0 scenes by path tracing on Vulkan compute, organised as a\n"
    "wavefront: separate passes for ray generation, intersection, shading and shadow rays.\n"
    "\n"
    "Commands:\n"
    "  render SCENE.gltf -o OUT.exr   offscreen render to OpenEXR, plus a PNG preview\n"
    "  view SCENE.gltf                window that refines the image progressively\n"
    "  converge SCENE.gltf -o DIR     error against time and samples per sampler and estimator\n"
    "  bench SCENE.gltf               frame timings per pass, throughput, queue occupancy\n"
    "  merge PART.exr ... -o OUT.exr  the parts of one render (--spp-offset) into one image\n"
    "\n"
    "Run 'wavefront COMMAND --help' for the options of a command.\n"
    "\n"
    "Exit codes: 0 done, 2 bad usage or bad input, 1 internal or device failure.\n";

int fail(const char* kind, const std::exception& error, int code) {
    std::fprintf(stderr, "wavefront: %s%s\n", kind, error.what());
    return code;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.empty()) {
            std::fputs(kTopHelp, stderr);
            return 2;
        }
        const std::string command = args.front();
        args.erase(args.begin());
        if (command == "--help" || command == "-h" || command == "help") {
            std::fputs(kTopHelp, stdout);
            return 0;
        }
        if (command == "render")
            return wf::runRenderCommand(args);
        if (command == "converge")
            return wf::runConvergeCommand(args);
        if (command == "bench")
            return wf::runBenchCommand(args);
        if (command == "merge")
            return wf::runMergeCommand(args);
        if (command == "view") {
#ifdef WF_HAVE_VIEWER
            return wf::runViewCommand(args);
#else
            throw wf::UsageError("this build has no viewer: configure with -DWF_BUILD_VIEWER=ON "
                                 "(needs libglfw3-dev and libimgui-dev)");
#endif
        }
        throw wf::UsageError("unknown command '" + command + "' (see wavefront --help)");
    } catch (const wf::UsageError& error) {
        return fail("", error, 2);
    } catch (const wf::InputError& error) {
        return fail("", error, 2);
    } catch (const std::exception& error) {
        return fail("internal error: ", error, 1);
    }
}
