// wavefront._wavefront: the compiled half of the Python module (the rest, and the API users
// see, is wavefront/__init__.py). Binds the Renderer (renderer.h), the device list, EXR and
// PNG files and the error metrics, and turns the core's exceptions into Python's.
#include <cstring>
#include <filesystem>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "errors.h"
#include "gpu/buffer.h"
#include "gpu/shader_compiler.h"
#include "image/error_metrics.h"
#include "image/exr_io.h"
#include "image/png_writer.h"
#include "module_support.h"
#include "renderer.h"

namespace pyb = pybind11;
namespace fs = std::filesystem;

namespace wf::py {
namespace {

std::string packageDir;

using FloatArray = pyb::array_t<float, pyb::array::c_style | pyb::array::forcecast>;

// (H, W, 3) float32 as the core's flat RGB; wavefront/__init__.py has checked the shape.
std::vector<float> flatRgb(const FloatArray& array) {
    if (array.ndim() != 3 || array.shape(2) != 3)
        throw UsageError("expected an array of shape (height, width, 3)");
    return std::vector<float>(array.data(), array.data() + array.size());
}

template <typename F> auto imageCall(F f) {
    try {
        return f();
    } catch (const InputError& error) {
        throw ImageFileError(error.what());
    }
}

pyb::tuple readExrFile(const std::string& path) {
    return imageCall([&] {
        ExrImage image = readExr(path);
        std::vector<ExrAttribute> attributes = readExrAttributes(path);
        pyb::array_t<float> array({pyb::ssize_t(image.height), pyb::ssize_t(image.width),
                                   pyb::ssize_t(3)});
        std::memcpy(array.mutable_data(), image.rgb.data(), image.rgb.size() * sizeof(float));
        pyb::dict header;
        for (const ExrAttribute& a : attributes) {
            if (a.type == 'i')
                header[a.name.c_str()] = std::stoll(a.text);
            else if (a.type == 'f')
                header[a.name.c_str()] = std::stod(a.text);
            else
                header[a.name.c_str()] = a.text;
        }
        return pyb::make_tuple(array, header);
    });
}

void writeExrFile(const std::string& path, const FloatArray& array, const pyb::dict& header) {
    std::vector<std::pair<std::string, std::string>> strings;
    std::vector<std::pair<std::string, float>> floats;
    std::vector<std::pair<std::string, int>> ints;
    for (const auto& [key, value] : header) {
        const std::string name = pyb::str(key);
        if (pyb::isinstance<pyb::bool_>(value))
            throw UsageError("EXR header '" + name + "': a bool has no EXR type (use 0 or 1)");
        else if (pyb::isinstance<pyb::int_>(value))
            ints.push_back({name, value.cast<int>()});
        else if (pyb::isinstance<pyb::float_>(value))
            floats.push_back({name, value.cast<float>()});
        else if (pyb::isinstance<pyb::str>(value))
            strings.push_back({name, value.cast<std::string>()});
        else
            throw UsageError("EXR header '" + name + "': values are str, int or float, not " +
                             std::string(pyb::str(value.get_type().attr("__name__"))));
    }
    const std::vector<float> rgb = flatRgb(array);
    imageCall([&] {
        writeExr(path, int(array.shape(1)), int(array.shape(0)), rgb, strings, floats, ints);
        return 0;
    });
}

void writePngFile(const std::string& path, const FloatArray& array) {
    const std::vector<float> rgb = flatRgb(array);
    imageCall([&] {
        writePngPreview(path, int(array.shape(1)), int(array.shape(0)), rgb);
        return 0;
    });
}

// relMSE, MSE and bias of `image` against `reference`, as converge measures them.
pyb::dict imageErrors(const FloatArray& image, const FloatArray& reference) {
    if (image.ndim() != reference.ndim() ||
        !std::equal(image.shape(), image.shape() + image.ndim(), reference.shape()))
        throw UsageError("the image and the reference differ in shape");
    if (image.size() == 0)
        throw UsageError("empty images have no error");
    const wf::ImageError e =
        imageError(std::vector<float>(image.data(), image.data() + image.size()),
                   std::vector<float>(reference.data(), reference.data() + reference.size()));
    pyb::dict out;
    out["relmse"] = e.relMse;
    out["mse"] = e.mse;
    out["bias"] = e.bias;
    return out;
}

} // namespace

void setPackageDir(const std::string& dir) { packageDir = dir; }

std::string moduleShaderDir() {
    if (const char* env = std::getenv("WAVEFRONT_SHADER_DIR"); env && *env)
        return env;
    const fs::path installed = fs::path(packageDir) / "shaders";
    if (!packageDir.empty() && fs::is_regular_file(installed / "raygen.comp"))
        return installed.string();
    return defaultShaderDir();
}

} // namespace wf::py

namespace {

// A Python exception class `wavefront.<name>` deriving from `base`.
pyb::handle newException(pyb::module_& m, const char* name, pyb::handle base, const char* doc) {
    const std::string qualified = std::string("wavefront.") + name;
    PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base.ptr(), nullptr);
    if (!type)
        throw pyb::error_already_set();
    m.add_object(name, pyb::handle(type));
    return pyb::handle(type);
}

} // namespace

PYBIND11_MODULE(_wavefront, m) {
    using namespace wf;
    using namespace wf::py;
    m.doc() = "The compiled half of the wavefront module: use `import wavefront`.";

    static pyb::handle error = newException(m, "Error", PyExc_RuntimeError,
                                            "Base of the errors this module raises.");
    static pyb::handle sceneError =
        newException(m, "SceneError", error, "A scene (or environment map) that cannot be used: the CLI's message.");
    static pyb::handle deviceError =
        newException(m, "DeviceError", error, "No Vulkan device, or the one asked for cannot be used.");
    static pyb::handle closedError =
        newException(m, "ClosedError", error, "A call on a Renderer after close().");
    static pyb::handle imageError =
        newException(m, "ImageError", error, "An image file that cannot be read or written.");
    pyb::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p)
                std::rethrow_exception(p);
        } catch (const UsageError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const InputError& e) {
            PyErr_SetString(sceneError.ptr(), e.what());
        } catch (const DeviceError& e) {
            PyErr_SetString(deviceError.ptr(), e.what());
        } catch (const ClosedError& e) {
            PyErr_SetString(closedError.ptr(), e.what());
        } catch (const ImageFileError& e) {
            PyErr_SetString(imageError.ptr(), e.what());
        } catch (const InternalError& e) {
            PyErr_SetString(error.ptr(), e.what());
        }
    });

    pyb::class_<LoadedScene, std::shared_ptr<LoadedScene>>(m, "LoadedScene")
        .def_readonly("path", &LoadedScene::path)
        .def_property_readonly("info", [](const LoadedScene& s) { return sceneInfo(s); });

    pyb::class_<py::Renderer>(m, "Renderer")
        .def(pyb::init<std::optional<int>, bool, bool, const std::string&>(),
             pyb::arg("device"), pyb::arg("validation"), pyb::arg("quiet"),
             pyb::arg("traversal") = "auto")
        .def("close", &py::Renderer::close)
        .def_property_readonly("closed", &py::Renderer::closed)
        .def_property_readonly("device_name", &py::Renderer::deviceName)
        .def_property_readonly("validation_messages", &py::Renderer::validationMessages)
        .def("load", &py::Renderer::load)
        .def("render", &py::Renderer::render)
        .def("begin", &py::Renderer::begin)
        .def("advance", &py::Renderer::advance)
        .def("converge", &py::Renderer::converge);

    m.def("devices", &listDevices);
    m.def("read_exr", &readExrFile);
    m.def("read_exr_channel", [](const std::string& path, const std::string& name) {
        return imageCall([&] { return readExrChannel(path, name); });
    });
    m.def("write_exr", &writeExrFile);
    m.def("write_png", &writePngFile);
    m.def("image_errors", &imageErrors);
    m.def("live_device_allocations", &Buffer::liveAllocations,
          "Buffers with device memory allocated now, in this process (every renderer).");
    m.def("set_package_dir", &setPackageDir);
    m.def("shader_dir", &moduleShaderDir);
}
