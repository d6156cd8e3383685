#include "page_layout.hpp"

#include <pango/pangocairo.h>

#include <algorithm>
#include <memory>

#include "markdown.hpp"

namespace legofeup::report::pages {
namespace {

constexpr double kCellPadding = 3.5;
constexpr double kFooterSize = 7.5;

struct GObjectDeleter {
    void operator()(void* object) const { g_object_unref(object); }
};
using LayoutPtr = std::unique_ptr<PangoLayout, GObjectDeleter>;
using FontPtr = std::unique_ptr<PangoFontDescription, decltype(&pango_font_description_free)>;
using IterPtr = std::unique_ptr<PangoLayoutIter, decltype(&pango_layout_iter_free)>;

void set_color(cairo_t* cr, const std::string& hex) {
    unsigned value = 0;
    for (std::size_t i = 1; i < hex.size(); ++i) {
        const char c = hex[i];
        const unsigned digit = c <= '9' ? static_cast<unsigned>(c - '0')
                                        : static_cast<unsigned>((c | 0x20) - 'a' + 10);
        value = value * 16 + digit;
    }
    cairo_set_source_rgb(cr, ((value >> 16) & 0xFF) / 255.0, ((value >> 8) & 0xFF) / 255.0,
                         (value & 0xFF) / 255.0);
}

// A layout of `markup` wrapped at `width` points. Sizes are absolute (one point per unit of
// the page), whatever resolution pango assumes for the surface.
LayoutPtr make_layout(cairo_t* cr, const std::string& markup, const TextStyle& style,
                      double width) {
    LayoutPtr layout(pango_cairo_create_layout(cr));
    FontPtr font(
        pango_font_description_from_string(style.monospace ? "DejaVu Sans Mono" : "DejaVu Sans"),
        pango_font_description_free);
    pango_font_description_set_absolute_size(font.get(), style.size * PANGO_SCALE);
    if (style.bold) {
        pango_font_description_set_weight(font.get(), PANGO_WEIGHT_BOLD);
    }
    pango_layout_set_font_description(layout.get(), font.get());
    pango_layout_set_width(layout.get(), pango_units_from_double(width));
    pango_layout_set_wrap(layout.get(), PANGO_WRAP_WORD_CHAR);
    pango_layout_set_indent(layout.get(), pango_units_from_double(-style.hanging));
    if (pango_parse_markup(markup.c_str(), -1, 0, nullptr, nullptr, nullptr, nullptr) != 0) {
        pango_layout_set_markup(layout.get(), markup.c_str(), -1);
    } else {
        pango_layout_set_text(layout.get(), markup.c_str(), -1);
    }
    return layout;
}

double layout_height(PangoLayout* layout) {
    int width = 0;
    int height = 0;
    pango_layout_get_size(layout, &width, &height);
    return pango_units_to_double(height);
}

// How wide `markup` is on one line (a list item's marker, for its hanging indent).
double markup_width(cairo_t* cr, const std::string& markup, const TextStyle& style) {
    const LayoutPtr layout = make_layout(cr, markup, style, -1.0);
    pango_layout_set_width(layout.get(), -1);
    int width = 0;
    int height = 0;
    pango_layout_get_size(layout.get(), &width, &height);
    return pango_units_to_double(width);
}

}  // namespace

PageLayout::PageLayout(PageSink& sink, std::string footer)
    : sink_(sink), footer_(std::move(footer)) {}

void PageLayout::start_page() {
    cr_ = sink_.begin_page();
    page_open_ = true;
    ++pages_;
    y_ = kMargin;
    cairo_set_source_rgb(cr_, 1.0, 1.0, 1.0);
    cairo_paint(cr_);
}

void PageLayout::end_page() {
    if (!page_open_) {
        return;
    }
    TextStyle style;
    style.size = kFooterSize;
    const std::string text = markdown::escape(footer_) + " — page " + std::to_string(pages_);
    const LayoutPtr layout = make_layout(cr_, text, style, text_width());
    pango_layout_set_alignment(layout.get(), PANGO_ALIGN_CENTER);
    cairo_set_source_rgb(cr_, 0.45, 0.45, 0.45);
    cairo_move_to(cr_, kMargin, kPageHeight - kMargin + 14.0);
    pango_cairo_show_layout(cr_, layout.get());
    sink_.end_page();
    page_open_ = false;
}

void PageLayout::ensure(double height) {
    if (!page_open_) {
        start_page();
    } else if (y_ + height > bottom() && y_ > kMargin) {
        end_page();
        start_page();
    }
}

void PageLayout::page_break() {
    end_page();
}

void PageLayout::space(double points) {
    if (page_open_) {
        y_ += points;
    }
}

void PageLayout::heading(const std::string& text, int level, double keep_with_next) {
    TextStyle style;
    style.bold = true;
    style.size = level == 1 ? 20.0 : level == 2 ? 15.0 : 11.5;
    style.space_after = level == 1 ? 4.0 : 5.0;
    // Keep a heading with the start of what follows it.
    ensure(std::max(level == 1 ? 80.0 : 70.0, keep_with_next + 30.0));
    if (y_ > kMargin) {
        y_ += level == 2 ? 12.0 : 6.0;
    }
    const std::string color = level == 2 ? "#1f66cc" : "#1a1a1a";
    paragraph("<span foreground=\"" + color + "\">" + markdown::escape(text) + "</span>", style);
    if (level == 2) {
        cairo_set_source_rgb(cr_, 0.8, 0.8, 0.87);
        cairo_set_line_width(cr_, 0.6);
        cairo_move_to(cr_, kMargin, y_ - style.space_after + 1.5);
        cairo_line_to(cr_, kMargin + text_width(), y_ - style.space_after + 1.5);
        cairo_stroke(cr_);
        y_ += 3.0;
    }
}

void PageLayout::paragraph(const std::string& markup, const TextStyle& style) {
    ensure(style.size * 1.5);
    // A bar or background spans the block from its own left edge (list items inside it are
    // indented further, the bar is not) and the gap below, so a block of paragraphs reads as
    // one.
    const bool framed = !style.bar.empty() || !style.background.empty();
    const double frame_left = kMargin + style.frame_indent;
    const double left = kMargin + style.indent + (framed ? 8.0 : 0.0);
    const auto frame = [&](double top, double height) {
        if (!style.background.empty()) {
            set_color(cr_, style.background);
            cairo_rectangle(cr_, frame_left, top, kMargin + text_width() - frame_left, height);
            cairo_fill(cr_);
        }
        if (!style.bar.empty()) {
            set_color(cr_, style.bar);
            cairo_rectangle(cr_, frame_left, top, 3.0, height);
            cairo_fill(cr_);
        }
    };
    const LayoutPtr layout = make_layout(cr_, markup, style, kMargin + text_width() - left);
    const IterPtr iter(pango_layout_get_iter(layout.get()), pango_layout_iter_free);
    do {
        PangoRectangle logical;
        pango_layout_iter_get_line_extents(iter.get(), nullptr, &logical);
        const double line_top = pango_units_to_double(logical.y);
        const double height = pango_units_to_double(logical.height);
        const double baseline = pango_units_to_double(pango_layout_iter_get_baseline(iter.get()));
        ensure(height);
        frame(y_, height);
        cairo_set_source_rgb(cr_, 0.1, 0.1, 0.1);
        cairo_move_to(cr_, left + pango_units_to_double(logical.x), y_ + baseline - line_top);
        pango_cairo_show_layout_line(cr_, pango_layout_iter_get_line_readonly(iter.get()));
        y_ += height;
    } while (pango_layout_iter_next_line(iter.get()) != 0);
    if (framed) {
        frame(y_, std::min(style.space_after, bottom() - y_));
    }
    y_ += style.space_after;
}

void PageLayout::markdown(const std::string& text, const TextStyle& style) {
    using markdown::Block;
    for (const Block& block : markdown::parse_blocks(text)) {
        switch (block.kind) {
            case Block::Kind::Paragraph:
                paragraph(markdown::render_inline(block.texts[0], markdown::kPango), style);
                break;
            case Block::Kind::Heading: {
                TextStyle bold = style;
                bold.bold = true;
                bold.size = style.size + 1.0;
                paragraph(markdown::render_inline(block.texts[0], markdown::kPango), bold);
                break;
            }
            case Block::Kind::BulletList:
            case Block::Kind::NumberedList:
                ensure(style.size * 1.5);
                for (std::size_t i = 0; i < block.texts.size(); ++i) {
                    const bool bullets = block.kind == Block::Kind::BulletList;
                    const std::string marker =
                        bullets ? std::string("•\u2002") : std::to_string(i + 1) + ".\u2002";
                    TextStyle item = style;
                    item.indent = style.indent + 10.0;
                    item.hanging = markup_width(cr_, marker, style);
                    item.space_after = i + 1 == block.texts.size() ? style.space_after : 2.0;
                    paragraph(marker + markdown::render_inline(block.texts[i], markdown::kPango),
                              item);
                }
                break;
            case Block::Kind::Code: {
                TextStyle code = style;
                code.monospace = true;
                code.size = style.size - 1.5;
                code.background = "#f2f2f2";
                std::string lines;
                for (const std::string& line : block.texts) {
                    lines += (lines.empty() ? "" : "\n") + markdown::escape(line);
                }
                paragraph(lines, code);
                break;
            }
        }
    }
}

void PageLayout::table(const std::vector<Column>& columns,
                       const std::vector<std::vector<std::string>>& rows) {
    TextStyle style;
    style.size = 8.5;
    TextStyle head = style;
    head.bold = true;
    struct Row {
        std::vector<LayoutPtr> cells;
        double height = 0.0;
    };
    const auto measure = [&](const std::vector<std::string>& cells, const TextStyle& cell_style) {
        Row row;
        for (std::size_t c = 0; c < columns.size(); ++c) {
            const double width = columns[c].fraction * text_width() - 2.0 * kCellPadding;
            row.cells.push_back(
                make_layout(cr_, c < cells.size() ? cells[c] : std::string(), cell_style, width));
            row.height =
                std::max(row.height, layout_height(row.cells.back().get()) + 2.0 * kCellPadding);
        }
        return row;
    };
    const auto draw = [&](const Row& row, bool header) {
        double x = kMargin;
        for (std::size_t c = 0; c < columns.size(); ++c) {
            const double width = columns[c].fraction * text_width();
            if (header) {
                cairo_set_source_rgb(cr_, 0.93, 0.95, 0.97);
                cairo_rectangle(cr_, x, y_, width, row.height);
                cairo_fill(cr_);
            }
            cairo_set_source_rgb(cr_, 0.8, 0.8, 0.87);
            cairo_set_line_width(cr_, 0.5);
            cairo_rectangle(cr_, x, y_, width, row.height);
            cairo_stroke(cr_);
            cairo_set_source_rgb(cr_, 0.1, 0.1, 0.1);
            cairo_move_to(cr_, x + kCellPadding, y_ + kCellPadding);
            pango_cairo_update_layout(cr_, row.cells[c].get());
            pango_cairo_show_layout(cr_, row.cells[c].get());
            x += width;
        }
        y_ += row.height;
    };
    std::vector<std::string> headings;
    for (const Column& column : columns) {
        headings.push_back(markdown::escape(column.heading));
    }
    ensure(60.0);
    const Row heading_row = measure(headings, head);
    draw(heading_row, true);
    for (const std::vector<std::string>& cells : rows) {
        const Row row = measure(cells, style);
        if (y_ + row.height > bottom()) {
            // The heading row again at the top of the next page.
            end_page();
            start_page();
            draw(heading_row, true);
        }
        draw(row, false);
    }
    y_ += 8.0;
}

// At the text width; shrunk (down to kSmallestFigure of that) to fill the rest of a page
// rather than leave it empty, otherwise on the next page.
constexpr double kSmallestFigure = 0.7;

double PageLayout::smallest_figure_height(const plot::Figure& figure) const {
    return figure.height() * text_width() / figure.width() * kSmallestFigure;
}

void PageLayout::figure(const plot::Figure& figure) {
    double scale = text_width() / figure.width();
    ensure(smallest_figure_height(figure));
    const double room = bottom() - y_;
    scale = std::min(scale, room / figure.height());
    const double left = kMargin + (text_width() - figure.width() * scale) / 2.0;
    cairo_save(cr_);
    cairo_translate(cr_, left, y_);
    cairo_scale(cr_, scale, scale);
    figure.draw(cr_);
    cairo_restore(cr_);
    y_ += figure.height() * scale + 10.0;
}

int PageLayout::finish() {
    end_page();
    return pages_;
}

}  // namespace legofeup::report::pages
