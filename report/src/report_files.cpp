// Writing the report's two files so that a failure never leaves a half file: each is written
// under a temporary name in the same directory and renamed into place once both are done.

#include <fstream>
#include <stdexcept>
#include <system_error>

#include "legofeup/report/student_report.hpp"
#include "report_pdf.hpp"

namespace legofeup::report {
namespace {

namespace fs = std::filesystem;

// Removes the temporary files it was given unless released.
class TemporaryFiles {
  public:
    fs::path add(const fs::path& final_path) {
        paths_.push_back(final_path.string() + ".partial");
        return paths_.back();
    }
    void release() { paths_.clear(); }
    ~TemporaryFiles() {
        for (const fs::path& path : paths_) {
            std::error_code ignored;
            fs::remove(path, ignored);
        }
    }

  private:
    std::vector<fs::path> paths_;
};

void write_text(const fs::path& path, const std::string& text, const fs::path& shown) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
        throw std::runtime_error("cannot write " + shown.string());
    }
}

}  // namespace

void write_report(const StudentReport& report, const fs::path& directory) {
    std::error_code error;
    fs::create_directories(directory, error);
    if (error) {
        throw std::runtime_error("cannot create " + directory.string() + ": " + error.message());
    }
    const fs::path html = directory / "report.html";
    const fs::path pdf = directory / "report.pdf";
    TemporaryFiles temporary;
    const fs::path html_partial = temporary.add(html);
    const fs::path pdf_partial = temporary.add(pdf);
    write_text(html_partial, report_html(report), html);
    try {
        write_report_pdf(report, pdf_partial);
    } catch (const std::runtime_error&) {
        throw std::runtime_error("cannot write " + pdf.string());
    }
    fs::rename(html_partial, html, error);
    if (!error) {
        fs::rename(pdf_partial, pdf, error);
    }
    if (error) {
        throw std::runtime_error("cannot write " + directory.string() + ": " + error.message());
    }
    temporary.release();
}

}  // namespace legofeup::report
