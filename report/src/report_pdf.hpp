#pragma once
// The student report as A4 pages: the same content as the HTML, laid out by PageLayout.

#include <filesystem>
#include <ostream>

#include "legofeup/report/student_report.hpp"
#include "page_layout.hpp"

namespace legofeup::report {

/// Draws the report's pages into `sink`; the number of pages.
int draw_report_pages(const StudentReport& report, pages::PageSink& sink);

/// Writes the report as a PDF to `out` (the file `shown_path` is written through it). Throws
/// std::runtime_error naming `shown_path` if cairo fails or `out` refuses the bytes.
void write_report_pdf(const StudentReport& report, std::ostream& out,
                      const std::filesystem::path& shown_path);

}  // namespace legofeup::report
