"""Keyword arguments to the CLI's own arguments.

Every option is the CLI flag of the same name (max_depth=16 is --max-depth 16), read and
checked by the CLI's C++ functions, so a render refuses what `wavefront render` refuses and
renders what it renders. Errors name the keyword, not the flag.
"""
import numbers
import re

# render()'s options: wavefront render's flags that shape an image (docs/cli.md).
RENDER_OPTIONS = (
    "spp", "time_limit", "target_error", "aov", "width", "height", "max_depth", "rr_depth",
    "light_sampling", "light_selection", "triangle_sampling", "sphere_sampling",
    "min_throughput", "clamp", "seed", "sampler", "texture_filter", "shade_split",
    "no_randomize", "spp_offset", "spp_total", "guiding", "error_replicates", "integrator",
    "bdpt_heuristic", "vcm_radius", "light_share", "spectral",
)
# load()'s options: those that change the scene rather than a render.
LOAD_OPTIONS = ("camera", "env", "instancing", "aperture", "focus_distance", "time", "frame",
                "fps", "animation", "variant")
SWITCHES = ("no_randomize",)


def flag_name(keyword):
    return "--" + keyword.replace("_", "-")


def to_flags(options):
    """[("max_depth", 16), ...] (None: the default) -> ["--max-depth", "16", ...]."""
    flags = []
    for keyword, value in options:
        if value is None:
            continue
        if keyword in SWITCHES:
            if not isinstance(value, bool):
                raise ValueError(f"{keyword} is True or False, got {value!r}")
            if value:
                flags.append(flag_name(keyword))
            continue
        if keyword == "aov" and not value:
            continue
        if keyword == "aov" and not isinstance(value, str):
            value = ",".join(str(name) for name in value)
        elif isinstance(value, bool):
            raise ValueError(f"{keyword} takes a number or a name, not {value!r}")
        elif isinstance(value, numbers.Integral):
            value = str(int(value))
        elif isinstance(value, numbers.Real):
            value = repr(float(value))
        elif not isinstance(value, str):
            raise ValueError(f"{keyword} takes a number or a name, not {type(value).__name__}")
        flags += [flag_name(keyword), value]
    return flags


def keyword_message(message):
    """The CLI's message with each --flag written as the keyword: --max-depth -> max_depth."""
    return re.sub(r"--([a-z][a-z0-9-]*)", lambda m: m.group(1).replace("-", "_"), message)
