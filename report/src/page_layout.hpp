#pragma once
// A4 pages laid out from top to bottom with cairo and pango: headings, wrapped paragraphs
// (Pango markup), tables, Markdown texts and figures, breaking pages where the next thing
// does not fit (paragraphs between lines, tables between rows). The pages go to a PageSink:
// a PDF file, or images to look at.

#include <cairo.h>

#include <string>
#include <vector>

#include "legofeup/report/figure.hpp"

namespace legofeup::report::pages {

inline constexpr double kPageWidth = 595.276;  // A4, points
inline constexpr double kPageHeight = 841.890;
inline constexpr double kMargin = 50.0;

/// Where the pages go. Each page is drawn in points, its origin at the top left.
class PageSink {
  public:
    virtual ~PageSink() = default;
    virtual cairo_t* begin_page() = 0;
    virtual void end_page() = 0;
};

struct TextStyle {
    double size = 10.0;  ///< points
    bool bold = false;
    bool monospace = false;
    double indent = 0.0;       ///< from the left margin, points
    double hanging = 0.0;      ///< lines after the first start this much further right
    double space_after = 6.0;  ///< points
    /// A bar in this colour (#rrggbb) down the left of the text (answers, conclusions).
    std::string bar;
    std::string background;     ///< #rrggbb behind the text, or empty
    double frame_indent = 0.0;  ///< where the bar and background start, from the margin
};

struct Column {
    std::string heading;
    double fraction;  ///< of the text width
};

class PageLayout {
  public:
    /// `footer` is printed at the foot of every page with the page number.
    PageLayout(PageSink& sink, std::string footer);
    PageLayout(const PageLayout&) = delete;
    PageLayout& operator=(const PageLayout&) = delete;

    /// A heading kept on one page with at least `keep_with_next` points of what follows.
    void heading(const std::string& text, int level, double keep_with_next = 0.0);
    /// A paragraph of Pango markup (invalid markup is shown as plain text).
    void paragraph(const std::string& markup, const TextStyle& style = {});
    /// Markdown as paragraphs, headings, lists and code, escaped for Pango.
    void markdown(const std::string& text, const TextStyle& style = {});
    /// Cells are Pango markup; the heading row is repeated on every page the table spans.
    void table(const std::vector<Column>& columns,
               const std::vector<std::vector<std::string>>& rows);
    /// The figure scaled to the text width, shrunk a little to fit the rest of this page, or
    /// else on the next page.
    void figure(const plot::Figure& figure);
    /// The least height figure() gives `figure`.
    double smallest_figure_height(const plot::Figure& figure) const;
    void space(double points);
    void page_break();

    /// Ends the last page; the number of pages drawn.
    int finish();

  private:
    double text_width() const { return kPageWidth - 2.0 * kMargin; }
    double bottom() const { return kPageHeight - kMargin; }
    void ensure(double height);
    void start_page();
    void end_page();

    PageSink& sink_;
    std::string footer_;
    cairo_t* cr_ = nullptr;
    double y_ = 0.0;
    int pages_ = 0;
    bool page_open_ = false;
};

}  // namespace legofeup::report::pages
