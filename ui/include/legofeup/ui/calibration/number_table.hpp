#pragma once
// A table of numbers typed by hand (calibration measurements): rows added and removed,
// every cell read with parse_number, and a bad cell refused with its row, column and text.

#include <QStringList>
#include <QTableWidget>
#include <optional>
#include <vector>

namespace legofeup::ui {

class NumberTable : public QTableWidget {
  public:
    /// One column per header ("A/D", "distance (m)").
    NumberTable(const QStringList& headers, QWidget* parent = nullptr);

    /// Appends a row (blank cells for missing values) and returns its index.
    int addRow(const std::vector<double>& values = {});
    /// Removes the selected rows (or the current one).
    void removeSelectedRows();
    /// Replaces every row.
    void setRows(const std::vector<std::vector<double>>& rows);
    void setNumber(int row, int column, double value);

    /// Every row's numbers in order; wholly blank rows are skipped. A cell that is blank in
    /// a row that is not, or not a number, makes it return nullopt with `problem` saying
    /// which ("Row 3, distance (m): '0,5' is not a number").
    std::optional<std::vector<std::vector<double>>> numbers(QString* problem) const;

  private:
    QStringList headers_;
};

}  // namespace legofeup::ui
