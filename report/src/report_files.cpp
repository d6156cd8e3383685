// Writing the report's two files so that a failure never leaves a half file: each is written
// through an AtomicFile (a temporary file in the same directory, renamed into place), and
// neither is renamed before both are complete.

#include <stdexcept>
#include <system_error>

#include "legofeup/fileio/atomic_file.hpp"
#include "legofeup/report/student_report.hpp"
#include "report_pdf.hpp"

namespace legofeup::report {

namespace fs = std::filesystem;

void write_report(const StudentReport& report, const fs::path& directory) {
    std::error_code error;
    fs::create_directories(directory, error);
    if (error) {
        throw std::runtime_error("cannot create " + directory.string() + ": " + error.message());
    }
    fileio::AtomicFile html(directory / "report.html");
    html.stream() << report_html(report);
    fileio::AtomicFile pdf(directory / "report.pdf");
    write_report_pdf(report, pdf.stream(), pdf.path());
    html.commit();
    pdf.commit();
}

}  // namespace legofeup::report
