#pragma once
// A table of numbers typed by hand (calibration measurements): rows added and removed,
// every cell read with parse_number, and a bad cell refused with its row, column and text.
// Optionally one last column of fixed choices (which sensor took the point), a drop-down in
// each row.

#include <QStringList>
#include <QTableWidget>
#include <optional>
#include <vector>

class QComboBox;

namespace legofeup::ui {

/// A column of fixed choices after the number columns; choices[0] is each new row's.
struct ChoiceColumn {
    QString header;
    QStringList choices;
};

class NumberTable : public QTableWidget {
  public:
    /// One column per header ("A/D", "distance (m)"), then `choice`'s if given.
    NumberTable(const QStringList& headers, QWidget* parent = nullptr,
                std::optional<ChoiceColumn> choice = std::nullopt);

    /// Appends a row (blank cells for missing values) and returns its index.
    int addRow(const std::vector<double>& values = {});
    /// Removes the selected rows (or the current one).
    void removeSelectedRows();
    /// Replaces every row.
    void setRows(const std::vector<std::vector<double>>& rows);
    void setNumber(int row, int column, double value);
    /// The index of the choice in `row` (0 without a choice column).
    int choice(int row) const;
    void setChoice(int row, int index);

    /// A row that is not wholly blank: its numbers and its choice.
    struct Row {
        std::vector<double> numbers;
        int choice = 0;
    };
    /// As numbers(), with each row's choice.
    std::optional<std::vector<Row>> rows(QString* problem) const;

    /// Every row's numbers in order; wholly blank rows are skipped. A cell that is blank in
    /// a row that is not, or not a number, makes it return nullopt with `problem` saying
    /// which ("Row 3, distance (m): '0,5' is not a number").
    std::optional<std::vector<std::vector<double>>> numbers(QString* problem) const;

  private:
    int numberColumns() const { return static_cast<int>(headers_.size()); }
    /// The drop-down of `row`'s choice, or nullptr without a choice column.
    QComboBox* choiceBox(int row) const;

    QStringList headers_;
    std::optional<ChoiceColumn> choice_;
};

}  // namespace legofeup::ui
