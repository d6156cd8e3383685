// Reading the comma-separated text the lessons write (traces, run-log records) in tests:
// no quoting, one record per line.
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace legofeup::lessons::csv_testing {

/// The cells of one line, split at every comma.
inline std::vector<std::string> cells_of(const std::string& line) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        cells.push_back(line.substr(start, comma - start));
        if (comma == std::string::npos) {
            return cells;
        }
        start = comma + 1;
    }
}

/// Each row after the header line as column name → cell; a row with another number of
/// cells than the header fails the test.
inline std::vector<std::map<std::string, std::string>> rows_of(const std::string& csv) {
    std::istringstream in(csv);
    std::string header;
    std::getline(in, header);
    const std::vector<std::string> names = cells_of(header);
    std::vector<std::map<std::string, std::string>> rows;
    for (std::string line; std::getline(in, line);) {
        const std::vector<std::string> cells = cells_of(line);
        EXPECT_EQ(cells.size(), names.size()) << line;
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < names.size() && i < cells.size(); ++i) {
            row[names[i]] = cells[i];
        }
        rows.push_back(row);
    }
    return rows;
}

}  // namespace legofeup::lessons::csv_testing
