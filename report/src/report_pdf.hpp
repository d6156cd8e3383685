#pragma once
// The student report as A4 pages: the same content as the HTML, laid out by PageLayout.

#include <filesystem>

#include "legofeup/report/student_report.hpp"
#include "page_layout.hpp"

namespace legofeup::report {

/// Draws the report's pages into `sink`; the number of pages.
int draw_report_pages(const StudentReport& report, pages::PageSink& sink);

/// Writes the report as a PDF file at `path`. Throws std::runtime_error naming the file.
void write_report_pdf(const StudentReport& report, const std::filesystem::path& path);

}  // namespace legofeup::report
