#pragma once
// Cairo's output callback (cairo_write_func_t) onto a std::ostream, so that PNG, SVG and PDF
// files are written through an AtomicFile's stream rather than by cairo opening the path.

#include <cairo.h>

#include <ostream>

namespace legofeup::report {

/// `closure` is the std::ostream*. A stream that refuses the bytes is a write error.
inline cairo_status_t write_to_stream(void* closure, const unsigned char* data,
                                      unsigned int length) {
    std::ostream& out = *static_cast<std::ostream*>(closure);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
    return out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

}  // namespace legofeup::report
