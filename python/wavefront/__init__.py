"""Wavefront from Python: render, compare and chart over the same C++ core as the CLI.

    import wavefront as wf
    with wf.Renderer() as r:
        scene = r.load("scenes/cornell_box.gltf")
        out = r.render(scene, width=256, spp=64, seed=0)
        wf.write_png("cornell.png", out.image)

Every option means what the `wavefront render` flag of the same name means (max_depth is
--max-depth) and is read by the CLI's own code: the same settings and seed give the CLI's
image bit for bit, and what the CLI refuses raises ValueError here. docs/python.md has it all.

Threads: a Renderer's calls take its lock, so one renderer may be shared but runs one call at
a time; renderers on different threads run at once (each owns its Vulkan device). The GIL is
released while the device works. Scenes are host data that any renderer can render.
"""
import atexit
import json
import threading
import weakref
from pathlib import Path

import numpy as np

from . import _wavefront as _core
from ._convergence import ConvergenceRuns
from ._options import LOAD_OPTIONS, keyword_message, to_flags
from ._wavefront import ClosedError, DeviceError, Error, ImageError, SceneError

__all__ = ["Renderer", "Scene", "RenderOutput", "ConvergenceRuns", "devices", "read_exr",
           "write_exr", "write_png", "relmse", "mse", "Error", "SceneError", "DeviceError",
           "ClosedError", "ImageError"]

_core.set_package_dir(str(Path(__file__).resolve().parent))


def _options(call, *args):
    """Runs a core call, naming keywords instead of flags in its ValueError."""
    try:
        return call(*args)
    except ValueError as error:
        raise ValueError(keyword_message(str(error))) from None


def devices():
    """The Vulkan devices: dicts of index, name, type, driver, api_version, subgroup_size."""
    return _core.devices()


class Scene:
    """A loaded glTF scene (host memory only; any Renderer can render it)."""

    def __init__(self, loaded):
        self._loaded = loaded
        self.path = loaded.path
        self.info = loaded.info  # triangles, instances, materials, lights, kinds, bounds, ...

    def __repr__(self):
        return f"<wavefront.Scene {self.path}: {self.info['triangles']} triangles>"


class RenderOutput:
    """One render: image (float32, (H, W, 3), C-contiguous, linear RGB, top row first), aov
    (name -> array), spp (samples per pixel done), seconds, stats (the --json object)."""

    def __init__(self, raw):
        self.image = raw["image"]
        self.aov = dict(raw["aov"])
        self.spp = raw["spp"]
        self.seconds = raw["seconds"]
        self.stats = json.loads(raw["stats"])
        self.height, self.width = self.image.shape[:2]

    def __repr__(self):
        return (f"<wavefront.RenderOutput {self.width}x{self.height}, {self.spp} spp, "
                f"{self.seconds:.3f} s>")


_live = weakref.WeakSet()


class Renderer:
    """Owns one Vulkan device, its shader compiler and the last render's GPU buffers.

    device: a device index (wf.devices()), None for WAVEFRONT_DEVICE or the first GPU.
    validation: the Khronos validation layer (messages on stderr; validation_messages counts).
    traversal: "auto" (the driver's ray tracing on a GPU that has it, else the project's BVH),
    "bvh" or "rt" (DeviceError where the device has no ray-tracing pipelines), as the CLI's
    --traversal; each result's stats say which ran.
    guiding: "auto" (path guiding where the measured rule of docs/guiding.md predicts a gain),
    "on" or "off", as the CLI's --guiding: the default of every render(), which may override it
    (render(..., guiding="on")); each result's stats say what auto decided (guidingDecision).
    integrator: "path" (the path tracer), "light" (light tracing), "bdpt" (bidirectional path
    tracing) or "vcm" (vertex connection and merging: consistent, not unbiased; vcm_radius as
    --vcm-radius; light_share as --light-share), as the CLI's --integrator:
    the default of every render(), which may override it (render(..., integrator="path")).
    Raises DeviceError when there is no usable device.
    """

    def __init__(self, device=None, validation=False, quiet=True, traversal="auto",
                 guiding="auto", integrator="path"):
        if guiding not in ("auto", "on", "off"):
            raise ValueError(f"guiding is 'auto', 'on' or 'off', not {guiding!r}")
        self._guiding = guiding
        if integrator not in ("path", "light", "bdpt", "vcm"):
            raise ValueError(
                f"integrator is 'path', 'light', 'bdpt' or 'vcm', not {integrator!r}")
        self._integrator = integrator
        if device is not None and (isinstance(device, bool) or not isinstance(device, int)):
            raise ValueError(f"device is a device index or None, not {device!r}")
        if traversal not in ("auto", "bvh", "rt"):
            raise ValueError(f"traversal is 'auto', 'bvh' or 'rt', not {traversal!r}")
        self._core = _core.Renderer(device, bool(validation), bool(quiet), traversal)
        _live.add(self)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        """Frees the buffers, pipelines and device, in that order; safe to call again."""
        self._core.close()

    @property
    def closed(self):
        return self._core.closed

    @property
    def device_name(self):
        return self._core.device_name

    @property
    def validation_messages(self):
        """Messages from the validation layer so far (0 without validation)."""
        return self._core.validation_messages

    def load(self, path, camera=None, env=None, instancing=None, aperture=None,
             focus_distance=None, time=None, frame=None, fps=None, animation=None,
             variant=None):
        """Loads a .gltf or .glb file. camera: the file's camera by name or index; env: an
        equirectangular EXR; instancing: "auto", "on" or "off"; aperture, focus_distance: a
        thin lens; time (seconds), or frame with fps (default 24): the pose of the file's
        animations, skins and morph targets (default: their start); animation: play only this
        one, by name or index (default: all at once); variant: the file's
        KHR_materials_variants variant whose materials the primitives take, by name or index
        (default: their own materials). Raises SceneError with the CLI's message
        for a file it cannot use (ValueError for options that contradict each other)."""
        if isinstance(camera, int) and not isinstance(camera, bool):
            camera = str(camera)
        if isinstance(animation, int) and not isinstance(animation, bool):
            animation = str(animation)
        if isinstance(variant, int) and not isinstance(variant, bool):
            variant = str(variant)
        values = dict(camera=camera, env=None if env is None else str(env),
                      instancing=instancing, aperture=aperture, focus_distance=focus_distance,
                      time=time, frame=frame, fps=fps, animation=animation, variant=variant)
        flags = to_flags((k, values[k]) for k in LOAD_OPTIONS)
        return Scene(_options(self._core.load, str(path), flags))

    def render(self, scene, *, spp=None, width=None, height=None, seed=None, sampler=None,
               max_depth=None, rr_depth=None, light_sampling=None, light_selection=None,
               triangle_sampling=None, sphere_sampling=None, min_throughput=None, clamp=None,
               texture_filter=None, shade_split=None, no_randomize=False, spp_offset=None,
               spp_total=None, aov=(), time_limit=None, target_error=None, guiding=None,
               error_replicates=None, integrator=None, bdpt_heuristic=None, vcm_radius=None,
               light_share=None, spectral=None, progress=None):
        """Renders `scene` and returns a RenderOutput. None means the CLI's default (spp 64,
        width 512, height from the camera's aspect, seed 0, sampler "sobol", max_depth 16,
        light_sampling "mis", ...). aov: names among albedo, normal, depth, variance, samples.
        progress(spp_done, spp_total, seconds) is called after each wave (with target_error,
        after each round). Ctrl-C ends the render after the pass in flight and raises
        KeyboardInterrupt; the renderer stays usable. guiding and integrator: None takes the
        Renderer's."""
        values = dict(locals())
        if values["guiding"] is None:
            values["guiding"] = self._guiding
        if values["integrator"] is None:
            values["integrator"] = self._integrator
        flags = self._flags(values)
        return RenderOutput(_options(self._core.render, self._scene(scene), flags, progress))

    def render_progressive(self, scene, *, spp=None, pass_spp=16, **options):
        """Yields a RenderOutput after every `pass_spp` samples per pixel, up to `spp`
        (default 64): the last is render()'s image for the same options. Takes render()'s
        options but time_limit, target_error and progress (the loop is the caller's)."""
        for name in ("time_limit", "target_error", "progress"):
            if name in options:
                raise ValueError(f"render_progressive takes no {name} (the caller's loop "
                                 "decides when to stop)")
        if not isinstance(pass_spp, int) or isinstance(pass_spp, bool) or pass_spp < 1:
            raise ValueError(f"pass_spp is a whole number of at least 1, got {pass_spp!r}")
        known = set(self.render.__kwdefaults__)
        unknown = set(options) - known
        if unknown:
            raise TypeError(f"render_progressive got unknown options {sorted(unknown)}")
        values = {**self.render.__kwdefaults__, **options, "spp": spp}
        if values["guiding"] is None:
            values["guiding"] = self._guiding
        if values["integrator"] is None:
            values["integrator"] = self._integrator
        flags = self._flags(values)
        loaded = self._scene(scene)
        session = _options(self._core.begin, loaded, flags)
        total = 64 if spp is None else spp
        return self._passes(session, total, pass_spp)

    def _passes(self, session, total, pass_spp):
        done = 0
        while done < total:
            out = RenderOutput(self._core.advance(session, min(pass_spp, total - done)))
            done = out.spp
            yield out

    def converge(self, scene, reference, methods=("sobol", "independent"), seeds=range(1, 6),
                 time=4.0, max_spp=65536, checkpoints=None, width=None, height=None,
                 max_depth=None, rr_depth=None, progress=None):
        """`wavefront converge` without the files: each method (as --methods words: sampler,
        bsdf|nee|mis, ...) rendered for each seed, error recorded at checkpoints whose spp
        doubles until a checkpoint's time passes `time` seconds or the next would pass
        max_spp (or at the given `checkpoints`). reference: an (H, W, 3) array, an EXR path,
        or a sample count to render one (seed 1000003, as the CLI). progress(method, seed,
        spp, seconds, relmse) after each checkpoint. Returns ConvergenceRuns."""
        loaded = self._scene(scene)
        if isinstance(reference, (str, Path)):
            reference = read_exr(reference)[0]
        elif isinstance(reference, int) and not isinstance(reference, bool):
            reference = self.render(scene, spp=reference, seed=1000003,
                                    width=128 if width is None else width, height=height,
                                    max_depth=max_depth, rr_depth=rr_depth).image
        reference = _rgb(reference, "reference")
        if width is None and height is None:
            height, width = reference.shape[:2]
        flags = to_flags([("width", width), ("height", height), ("max_depth", max_depth),
                          ("rr_depth", rr_depth)])
        if isinstance(methods, str):
            methods = [methods]
        seeds = [int(s) for s in seeds]
        records = _options(self._core.converge, loaded, flags, list(methods), seeds,
                           float(time), int(max_spp), list(checkpoints or []),
                           reference.ravel(), progress)
        return ConvergenceRuns(records)

    def _scene(self, scene):
        if not isinstance(scene, Scene):
            raise TypeError(f"expected a wavefront.Scene (from Renderer.load), got "
                            f"{type(scene).__name__}")
        return scene._loaded

    @staticmethod
    def _flags(values):
        from ._options import RENDER_OPTIONS
        options = [(k, values[k]) for k in RENDER_OPTIONS]
        return _options(to_flags, options)


@atexit.register
def _close_all():
    # Every renderer still open, before the interpreter tears modules down.
    for renderer in list(_live):
        renderer.close()


def _rgb(array, what="image"):
    array = np.ascontiguousarray(array, dtype=np.float32)
    if array.ndim != 3 or array.shape[2] != 3:
        raise ValueError(f"{what} must have shape (height, width, 3), got {array.shape}")
    return array


def read_exr(path):
    """(image, header): float32 (H, W, 3) RGB and the header's str, int and float attributes."""
    return _core.read_exr(str(path))


def write_exr(path, image, header=None):
    """Writes float32 RGB (ZIP), with `header` (str, int or float values) as attributes."""
    _core.write_exr(str(path), _rgb(image), dict(header or {}))


def write_png(path, image):
    """The CLI's 8-bit sRGB preview: exposure 1, clamped, NaN black."""
    _core.write_png(str(path), _rgb(image))


def _errors(image, reference):
    image = np.ascontiguousarray(image, dtype=np.float32)
    reference = np.ascontiguousarray(reference, dtype=np.float32)
    if image.shape != reference.shape:
        raise ValueError(f"image {image.shape} and reference {reference.shape} differ in shape")
    return _core.image_errors(image, reference)


def relmse(image, reference):
    """mean((x - r)^2 / (r^2 + 0.01)) over pixels and channels, as converge measures it."""
    return _errors(image, reference)["relmse"]


def mse(image, reference):
    """mean((x - r)^2) over pixels and channels."""
    return _errors(image, reference)["mse"]


def live_device_allocations():
    """Buffers with device memory allocated now, in this process (a leak check's number)."""
    return _core.live_device_allocations()
