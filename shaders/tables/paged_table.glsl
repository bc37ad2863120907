// One read-only table of uint texels spread over up to WF_MAX_TABLE_PAGES buffers ("pages") of
// 2^shift entries each, where one buffer would pass the device's limit, and its reader.
// Included once per table, after defining:
//   WF_PAGED_NAME          the reader, uvec4 NAME(uint entry, uint part); its images are
//                          NAMEPage0 .. NAMEPage7
//   WF_PAGED_FORMAT        the texels' image format (rgba32ui, rg32ui)
//   WF_PAGED_BINDING       page 0's binding; WF_PAGED_BINDING_PAGE1 the first of pages 1-7
//   WF_PAGED_PAGES         pages in use, WF_PAGED_SHIFT log2 of the entries a page holds
//                          (1 and 31 for one buffer, which compiles the plain read)
//   WF_PAGED_TEXELS        texels an entry
// and undefines them all, so that the next table defines its own. A power of two of entries
// a page keeps the division out of traversal's inner loops: a read is a shift, a mask and a
// switch on the page.
#ifndef WF_PAGED_TABLE_MACROS
#define WF_PAGED_TABLE_MACROS
#define WF_PASTE_(a, b) a##b
#define WF_PASTE(a, b) WF_PASTE_(a, b)
#define WF_PAGE(k) WF_PASTE(WF_PAGED_NAME, Page##k)
#define WF_DECLARE_PAGE(k)                                                                     \
    layout(binding = WF_PAGED_BINDING_PAGE1 + k - 1, WF_PAGED_FORMAT) uniform readonly restrict \
        uimageBuffer WF_PAGE(k);
#define WF_READ_PAGE(k)                                                                        \
    case k:                                                                                    \
        return imageLoad(WF_PAGE(k), int(texel));
#endif

layout(binding = WF_PAGED_BINDING, WF_PAGED_FORMAT) uniform readonly restrict uimageBuffer
    WF_PAGE(0);
#if WF_PAGED_PAGES > 1
WF_DECLARE_PAGE(1)
#endif
#if WF_PAGED_PAGES > 2
WF_DECLARE_PAGE(2)
#endif
#if WF_PAGED_PAGES > 3
WF_DECLARE_PAGE(3)
#endif
#if WF_PAGED_PAGES > 4
WF_DECLARE_PAGE(4)
#endif
#if WF_PAGED_PAGES > 5
WF_DECLARE_PAGE(5)
#endif
#if WF_PAGED_PAGES > 6
WF_DECLARE_PAGE(6)
#endif
#if WF_PAGED_PAGES > 7
WF_DECLARE_PAGE(7)
#endif

uvec4 WF_PAGED_NAME(uint entry, uint part) {
#if WF_PAGED_PAGES > 1
    const uint texel = (entry & ((1u << WF_PAGED_SHIFT) - 1u)) * WF_PAGED_TEXELS + part;
    switch (int(entry >> WF_PAGED_SHIFT)) {
    WF_READ_PAGE(1)
#if WF_PAGED_PAGES > 2
    WF_READ_PAGE(2)
#endif
#if WF_PAGED_PAGES > 3
    WF_READ_PAGE(3)
#endif
#if WF_PAGED_PAGES > 4
    WF_READ_PAGE(4)
#endif
#if WF_PAGED_PAGES > 5
    WF_READ_PAGE(5)
#endif
#if WF_PAGED_PAGES > 6
    WF_READ_PAGE(6)
#endif
#if WF_PAGED_PAGES > 7
    WF_READ_PAGE(7)
#endif
    default:
        return imageLoad(WF_PAGE(0), int(texel));
    }
#else
    return imageLoad(WF_PAGE(0), int(entry * WF_PAGED_TEXELS + part));
#endif
}

#undef WF_PAGED_NAME
#undef WF_PAGED_FORMAT
#undef WF_PAGED_BINDING
#undef WF_PAGED_BINDING_PAGE1
#undef WF_PAGED_PAGES
#undef WF_PAGED_SHIFT
#undef WF_PAGED_TEXELS
