// What the module tells about devices (wavefront.devices()) and loaded scenes (Scene.info).
#include <vulkan/vulkan.h>

#include <pybind11/stl.h>

#include "passes/shade_kinds.h"
#include "renderer.h"

namespace wf::py {

pyb::list listDevices() {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "wavefront.devices";
    app.apiVersion = VK_API_VERSION_1_2;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    VkInstance instance = VK_NULL_HANDLE;
    pyb::list devices;
    if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS)
        return devices; // no driver: no devices
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> physical(count);
    vkEnumeratePhysicalDevices(instance, &count, physical.data());
    for (uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceSubgroupProperties subgroup{
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
        VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
        driver.pNext = &subgroup;
        VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
        properties.pNext = &driver;
        vkGetPhysicalDeviceProperties2(physical[i], &properties);
        const VkPhysicalDeviceProperties& p = properties.properties;
        const char* type = p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU     ? "discrete"
                           : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU ? "integrated"
                           : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU    ? "virtual"
                           : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU            ? "cpu"
                                                                                    : "other";
        pyb::dict d;
        d["index"] = i;
        d["name"] = std::string(p.deviceName);
        d["type"] = type;
        d["driver"] = std::string(driver.driverName) + " " + driver.driverInfo;
        d["api_version"] = std::to_string(VK_API_VERSION_MAJOR(p.apiVersion)) + "." +
                           std::to_string(VK_API_VERSION_MINOR(p.apiVersion)) + "." +
                           std::to_string(VK_API_VERSION_PATCH(p.apiVersion));
        d["subgroup_size"] = subgroup.subgroupSize;
        devices.append(d);
    }
    vkDestroyInstance(instance, nullptr);
    return devices;
}

pyb::dict sceneInfo(const LoadedScene& scene) {
    const SceneSummary& s = scene.summary;
    const PreparedScene& p = *scene.prepared;
    pyb::dict info;
    info["triangles"] = s.triangleCount;
    info["instances"] = p.instances.size();
    info["instanced_triangles"] = p.instancedTriangles;
    info["materials"] = s.materialCount;
    info["emissive_triangles"] = s.emissiveTriangleCount;
    pyb::dict lights;
    lights["emitters"] = p.lights.emitters.size();
    lights["point"] = s.pointLights;
    lights["spot"] = s.spotLights;
    lights["directional"] = s.directionalLights;
    lights["sphere"] = s.sphereLights;
    info["lights"] = lights;
    const uint32_t present = shadeKindsPresent(p.materials);
    pyb::list kinds;
    const char* names[kShadeKinds] = {"diffuse", "specular", "general"};
    for (uint32_t k = 0; k < kShadeKinds; ++k)
        if (present & (1u << k))
            kinds.append(names[k]);
    info["kinds"] = kinds;
    info["cameras"] = s.cameraCount;
    pyb::list variants; // KHR_materials_variants
    for (const std::string& name : s.variantNames)
        variants.append(name);
    info["variants"] = variants;
    info["variant"] = s.variant < 0 ? pyb::object(pyb::none()) : pyb::int_(s.variant);
    info["textures"] = s.imageCount;
    info["bounds"] = pyb::make_tuple(pyb::make_tuple(s.boundsLo.x, s.boundsLo.y, s.boundsLo.z),
                                     pyb::make_tuple(s.boundsHi.x, s.boundsHi.y, s.boundsHi.z));
    info["load_seconds"] = s.loadSeconds;
    info["summary"] = describe(s);
    return info;
}

} // namespace wf::py
