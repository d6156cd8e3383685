#include "legofeup/ui/calibration/number_table.hpp"

#include <QComboBox>
#include <QHeaderView>
#include <algorithm>
#include <set>

#include "legofeup/ui/panels/number_text.hpp"

namespace legofeup::ui {

NumberTable::NumberTable(const QStringList& headers, QWidget* parent,
                         std::optional<ChoiceColumn> choice)
    : QTableWidget(0, static_cast<int>(headers.size()) + (choice ? 1 : 0), parent),
      headers_(headers),
      choice_(std::move(choice)) {
    setHorizontalHeaderLabels(choice_ ? headers + QStringList{choice_->header} : headers);
    horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    setSelectionBehavior(QAbstractItemView::SelectRows);
}

int NumberTable::addRow(const std::vector<double>& values) {
    const int row = rowCount();
    insertRow(row);
    for (int column = 0; column < numberColumns(); ++column) {
        auto* item = new QTableWidgetItem;
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        setItem(row, column, item);
        if (static_cast<std::size_t>(column) < values.size()) {
            setNumber(row, column, values[static_cast<std::size_t>(column)]);
        }
    }
    if (choice_) {
        // The drop-down shows the choice; the cell's item holds its text, so that a change
        // is an itemChanged like an edited number.
        const int column = numberColumns();
        auto* item = new QTableWidgetItem(choice_->choices.value(0));
        item->setFlags(item->flags() & ~Qt::ItemIsEditable);
        setItem(row, column, item);
        auto* box = new QComboBox(this);
        box->addItems(choice_->choices);
        connect(box, &QComboBox::currentTextChanged, this,
                [item](const QString& text) { item->setText(text); });
        setCellWidget(row, column, box);
    }
    return row;
}

QComboBox* NumberTable::choiceBox(int row) const {
    return choice_ ? qobject_cast<QComboBox*>(cellWidget(row, numberColumns())) : nullptr;
}

int NumberTable::choice(int row) const {
    const QComboBox* box = choiceBox(row);
    return box != nullptr ? box->currentIndex() : 0;
}

void NumberTable::setChoice(int row, int index) {
    if (QComboBox* box = choiceBox(row)) {
        box->setCurrentIndex(index);
    }
}

void NumberTable::removeSelectedRows() {
    std::set<int> rows;
    for (const QModelIndex& index : selectionModel()->selectedIndexes()) {
        rows.insert(index.row());
    }
    if (rows.empty() && currentRow() >= 0) {
        rows.insert(currentRow());
    }
    for (auto row = rows.rbegin(); row != rows.rend(); ++row) {
        removeRow(*row);
    }
}

void NumberTable::setRows(const std::vector<std::vector<double>>& rows) {
    setRowCount(0);
    for (const std::vector<double>& values : rows) {
        addRow(values);
    }
}

void NumberTable::setNumber(int row, int column, double value) {
    QTableWidgetItem* cell = item(row, column);
    if (cell == nullptr) {
        cell = new QTableWidgetItem;
        cell->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        setItem(row, column, cell);
    }
    cell->setText(number_text(value));
}

std::optional<std::vector<std::vector<double>>> NumberTable::numbers(QString* problem) const {
    const std::optional<std::vector<Row>> read = rows(problem);
    if (!read) {
        return std::nullopt;
    }
    std::vector<std::vector<double>> numbers;
    numbers.reserve(read->size());
    for (const Row& row : *read) {
        numbers.push_back(row.numbers);
    }
    return numbers;
}

std::optional<std::vector<NumberTable::Row>> NumberTable::rows(QString* problem) const {
    std::vector<Row> rows;
    for (int row = 0; row < rowCount(); ++row) {
        QStringList texts;
        for (int column = 0; column < numberColumns(); ++column) {
            const QTableWidgetItem* cell = item(row, column);
            texts << (cell != nullptr ? cell->text().trimmed() : QString());
        }
        if (std::all_of(texts.begin(), texts.end(), [](const QString& t) { return t.isEmpty(); })) {
            continue;
        }
        std::vector<double> values;
        for (int column = 0; column < numberColumns(); ++column) {
            const QString& text = texts[column];
            const std::optional<double> value = parse_number(text);
            if (!value) {
                if (problem != nullptr) {
                    *problem =
                        text.isEmpty()
                            ? QObject::tr("Row %1, %2: empty").arg(row + 1).arg(headers_[column])
                            : QObject::tr("Row %1, %2: '%3' is not a number%4")
                                  .arg(row + 1)
                                  .arg(headers_[column], text,
                                       text.contains(QLatin1Char(','))
                                           ? QObject::tr(" (use a point for decimals)")
                                           : QString());
                }
                return std::nullopt;
            }
            values.push_back(*value);
        }
        rows.push_back({std::move(values), choice(row)});
    }
    return rows;
}

}  // namespace legofeup::ui
