#include "render/gpu_scene/table_pages.h"

#include "errors.h"
#include "shaders/types/scene_types.h"

namespace wf {

TablePages tablePaging(uint64_t entries, uint64_t entryBytes, uint64_t pageBytes,
                       const char* table) {
    if (entries * entryBytes <= pageBytes)
        return {};
    TablePages pages;
    pages.shift = 0;
    while (pages.shift < 30 && (uint64_t(2) << pages.shift) * entryBytes <= pageBytes)
        ++pages.shift;
    const uint64_t count = (entries + pages.entriesPerPage() - 1) / pages.entriesPerPage();
    if (count > WF_MAX_TABLE_PAGES) {
        const uint64_t held = WF_MAX_TABLE_PAGES * pages.entriesPerPage() * entryBytes;
        throw InputError("the scene's " + std::string(table) + " need " +
                         std::to_string((entries * entryBytes) >> 20) + " MiB, over the " +
                         std::to_string(held >> 20) + " MiB that " +
                         std::to_string(WF_MAX_TABLE_PAGES) + " buffers of " +
                         std::to_string((pages.entriesPerPage() * entryBytes) >> 20) +
                         " MiB (the device's limit) hold");
    }
    pages.count = static_cast<uint32_t>(count);
    return pages;
}

void bindPages(DescriptorBindings& bindings, const std::vector<Buffer>& pages,
               uint32_t firstBinding, uint32_t otherBindings, BufferAccess access) {
    for (size_t page = 0; page < pages.size(); ++page)
        bindings.push_back({page == 0 ? firstBinding : otherBindings + uint32_t(page) - 1,
                            &pages[page], access});
}

} // namespace wf
