#include "legofeup/ui/window/connect_dialog.hpp"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include "legofeup/ui/session/nxt_address.hpp"
#include "legofeup/ui/window/app_settings.hpp"
#include "legofeup/ui/window/bluetooth_scan.hpp"

namespace legofeup::ui {
namespace {

constexpr int kScanSeconds = 15;

/// A wrapped message with room for `lines` lines, so a longer one never resizes the dialog
/// (nor is cut off: the dialog is as wide as kDialogColumns characters).
QLabel* note(const QString& text, QWidget* parent, int lines = 1) {
    auto* label = new QLabel(text, parent);
    label->setWordWrap(true);
    label->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setMinimumHeight(label->fontMetrics().lineSpacing() * lines + 4);
    return label;
}

constexpr int kDialogColumns = 72;

}  // namespace

ConnectDialog::ConnectDialog(const LinkChoice& current, QWidget* parent)
    : QDialog(parent), current_(current) {
    setObjectName(QStringLiteral("connectDialog"));
    setWindowTitle(tr("Connect to an NXT"));
    setMinimumWidth(fontMetrics().averageCharWidth() * kDialogColumns);

    // The brick: its address, the recent ones, the nearby ones.
    auto* brick = new QGroupBox(tr("The brick"), this);
    auto* grid = new QGridLayout(brick);
    grid->setColumnStretch(1, 1);
    int row = 0;
    const auto add_row = [&](const QString& label_text, QWidget* buddy, QLayoutItem* field) {
        if (!label_text.isEmpty()) {
            auto* label = new QLabel(label_text, brick);
            label->setBuddy(buddy);
            // Beside a one-line field, level with its text; beside a list, at its top.
            const bool tall = qobject_cast<QListWidget*>(buddy) != nullptr;
            grid->addWidget(label, row, 0,
                            Qt::AlignLeft | (tall ? Qt::AlignTop : Qt::AlignVCenter));
        }
        grid->addItem(field, row, 1);
        ++row;
    };
    address_ = new QLineEdit(current.nxt_address, brick);
    address_->setObjectName(QStringLiteral("nxtAddress"));
    address_->setPlaceholderText(QStringLiteral("bt:00:16:53:XX:XX:XX"));
    address_->setToolTip(
        tr("bt:XX:XX:XX:XX:XX:XX (Bluetooth; a bare address works too), serial:/dev/rfcomm0 "
           "(a bound RFCOMM device or a USB serial adapter) or tcp:HOST:PORT (an emulator "
           "or a bridge)"));
    address_->setMinimumWidth(fontMetrics().horizontalAdvance(QLatin1Char('x')) * 40);
    add_row(tr("&Address:"), address_, new QWidgetItem(address_));
    address_message_ = note({}, brick, 2);
    address_message_->setObjectName(QStringLiteral("nxtAddressMessage"));
    add_row({}, nullptr, new QWidgetItem(address_message_));

    recent_ = new QListWidget(brick);
    recent_->setObjectName(QStringLiteral("recentRobots"));
    recent_->addItems(preferences::kRecentRobots.read());
    recent_->setMaximumHeight(fontMetrics().height() * 5);
    recent_->setToolTip(
        tr("The bricks connected to before, most recent first: click one to "
           "use it"));
    remove_recent_ = new QPushButton(tr("&Remove"), brick);
    remove_recent_->setToolTip(tr("Forget the selected robot"));
    remove_recent_->setEnabled(false);
    auto* recent_row = new QHBoxLayout;
    recent_row->addWidget(recent_, 1);
    recent_row->addWidget(remove_recent_, 0, Qt::AlignTop);
    add_row(tr("Recent robo&ts:"), recent_, recent_row);

    scan_button_ = new QPushButton(tr("&Scan"), brick);
    scan_button_->setObjectName(QStringLiteral("scanButton"));
    scan_button_->setToolTip(
        tr("Look for Bluetooth devices nearby for %1 s (needs BlueZ and an adapter). NXT "
           "bricks, whose addresses start with %2, are shown in bold.")
            .arg(kScanSeconds)
            .arg(QLatin1String(kLegoBluetoothPrefix)));
    scan_message_ = note(tr("Switch the brick on, then scan, or type its address."), brick, 4);
    scan_message_->setObjectName(QStringLiteral("scanMessage"));
    auto* scan_row = new QHBoxLayout;
    scan_row->addWidget(scan_button_);
    scan_row->addStretch(1);
    add_row(tr("Nearby:"), scan_button_, scan_row);
    add_row({}, nullptr, new QWidgetItem(scan_message_));
    found_ = new QListWidget(brick);
    found_->setObjectName(QStringLiteral("foundDevices"));
    found_->setMaximumHeight(fontMetrics().height() * 6);
    found_->setVisible(false);
    add_row({}, nullptr, new QWidgetItem(found_));
    grid->setRowStretch(row, 1);  // spare height goes below, not between the rows

    // How to run it.
    auto* options = new QGroupBox(tr("Options"), this);
    auto* options_form = new QFormLayout(options);
    relay_ = new QCheckBox(tr("Use the &relay program on the brick (faster cycles)"), options);
    relay_->setObjectName(QStringLiteral("nxtRelay"));
    relay_->setChecked(current.relay);
    relay_->setToolTip(
        tr("Needs legofeup.rxe downloaded to the brick (resources/nxt, see docs/nxt.md). The "
           "program packs the counts and A/D values into one message, so each cycle costs "
           "one Bluetooth round trip instead of several. Off: the stock firmware's direct "
           "commands, nothing to install."));
    options_form->addRow(relay_);
    profile_ = new QLineEdit(current.robot_profile, options);
    profile_->setObjectName(QStringLiteral("nxtProfile"));
    profile_->setPlaceholderText(tr("none: the configuration's robot"));
    profile_->setToolTip(
        tr("A robot profile (TOML, written by Tools ▸ IR sensor calibration "
           "and UMBmark): this robot's wheels, wheel base and IR curve"));
    auto* browse = new QPushButton(tr("&Browse…"), options);
    auto* profile_row = new QHBoxLayout;
    profile_row->addWidget(profile_, 1);
    profile_row->addWidget(browse);
    auto* profile_label = new QLabel(tr("Robot &profile:"), options);
    profile_label->setBuddy(profile_);
    options_form->addRow(profile_label, profile_row);
    emulated_ = new QCheckBox(tr("Rehearse with an &emulated brick (no robot needed)"), options);
    emulated_->setObjectName(QStringLiteral("nxtEmulated"));
    emulated_->setChecked(current.emulated);
    emulated_->setToolTip(
        tr("Runs an emulated NXT inside the application, on the simulator, and connects to "
           "it over loopback TCP: the whole real-robot path, with the simulator's ground "
           "truth. The address is not used."));
    options_form->addRow(emulated_);

    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    okButton()->setText(tr("Use this robot"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(brick);
    layout->addWidget(options);
    layout->addWidget(note(tr("The robot is connected when the run starts (Start, F5) and "
                              "released when it stops; after a failure, Start connects again."),
                           this));
    layout->addWidget(buttons_);

    scan_ = new BluetoothScan(this);
    connect(scan_, &BluetoothScan::deviceFound, this, &ConnectDialog::deviceFound);
    connect(scan_, &BluetoothScan::finished, this, &ConnectDialog::scanFinished);
    connect(scan_button_, &QPushButton::clicked, this, &ConnectDialog::startScan);
    connect(address_, &QLineEdit::textChanged, this, &ConnectDialog::validate);
    connect(emulated_, &QCheckBox::toggled, this, &ConnectDialog::validate);
    connect(recent_, &QListWidget::itemClicked, this,
            [this](QListWidgetItem* item) { useAddress(item->text()); });
    connect(recent_, &QListWidget::itemSelectionChanged, this,
            [this] { remove_recent_->setEnabled(!recent_->selectedItems().isEmpty()); });
    connect(remove_recent_, &QPushButton::clicked, this, &ConnectDialog::removeRecent);
    connect(found_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        useAddress(QStringLiteral("bt:") + item->data(Qt::UserRole).toString());
    });
    connect(browse, &QPushButton::clicked, this, &ConnectDialog::chooseProfile);
    connect(buttons_, &QDialogButtonBox::accepted, this, &ConnectDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &ConnectDialog::reject);
    validate();
}

ConnectDialog::~ConnectDialog() = default;

QPushButton* ConnectDialog::okButton() const {
    return buttons_->button(QDialogButtonBox::Ok);
}

LinkChoice ConnectDialog::choice() const {
    LinkChoice choice = current_;
    choice.kind = LinkKind::Nxt;
    choice.nxt_address = normalized_nxt_address(address_->text());
    choice.relay = relay_->isChecked();
    choice.robot_profile = profile_->text().trimmed();
    choice.emulated = emulated_->isChecked();
    return choice;
}

QString ConnectDialog::problem() const {
    return emulated_->isChecked() ? QString() : nxt_address_problem(address_->text());
}

void ConnectDialog::validate() {
    const bool emulated = emulated_->isChecked();
    address_->setEnabled(!emulated);
    recent_->setEnabled(!emulated);
    scan_button_->setEnabled(!emulated && !scan_->active());
    found_->setEnabled(!emulated);
    const QString why = problem();
    okButton()->setEnabled(why.isEmpty());
    // Red for a mistake; nothing typed yet is no mistake, only a hint.
    const bool mistake = !why.isEmpty() && !address_->text().trimmed().isEmpty();
    QPalette palette = address_message_->palette();
    palette.setColor(QPalette::WindowText, mistake ? QColor(0xc6, 0x28, 0x28)
                                                   : this->palette().color(QPalette::WindowText));
    address_message_->setPalette(palette);
    if (emulated) {
        address_message_->setText(tr("Not used: the emulated brick listens on loopback."));
    } else if (!why.isEmpty()) {
        address_message_->setText(why);
    } else {
        address_message_->setText(tr("✓ %1").arg(normalized_nxt_address(address_->text())));
    }
}

void ConnectDialog::useAddress(const QString& address) {
    address_->setText(address);
    address_->setFocus();
}

void ConnectDialog::removeRecent() {
    for (QListWidgetItem* item : recent_->selectedItems()) {
        delete item;
    }
    QStringList recent;
    for (int i = 0; i < recent_->count(); ++i) {
        recent << recent_->item(i)->text();
    }
    preferences::kRecentRobots.write(recent);
}

void ConnectDialog::chooseProfile() {
    const QString start = profile_->text().isEmpty() ? QString() : profile_->text();
    const QString path = QFileDialog::getOpenFileName(this, tr("Robot profile"), start,
                                                      tr("Robot profiles (*.toml);;All files (*)"));
    if (!path.isEmpty()) {
        profile_->setText(path);
    }
}

void ConnectDialog::startScan() {
    found_->clear();
    found_->setVisible(false);
    scan_message_->setText(tr("Scanning for %1 s…").arg(kScanSeconds));
    scan_->start(kScanSeconds);
    validate();  // the button waits for the scan's end
}

void ConnectDialog::deviceFound(const QString& address, const QString& name) {
    const bool lego = is_lego_bluetooth_address(address);
    const QString label = QStringLiteral("%1  %2%3")
                              .arg(address, name.isEmpty() ? tr("(no name)") : name,
                                   lego ? tr("  — LEGO NXT") : QString());
    auto* item = new QListWidgetItem(label);
    item->setData(Qt::UserRole, address);
    if (lego) {
        QFont bold = item->font();
        bold.setBold(true);
        item->setFont(bold);
        item->setToolTip(tr("A LEGO brick (its address starts with %1): click to use it")
                             .arg(QLatin1String(kLegoBluetoothPrefix)));
        found_->insertItem(0, item);  // the bricks first
    } else {
        found_->addItem(item);
    }
    found_->setVisible(true);
}

void ConnectDialog::scanFinished(const QString& problem) {
    if (!problem.isEmpty()) {
        scan_message_->setText(problem);
    } else if (found_->count() == 0) {
        scan_message_->setText(
            tr("No device answered. Is the brick on, with Bluetooth "
               "switched on and visible (NXT menu ▸ Bluetooth)?"));
    } else {
        scan_message_->setText(tr("Devices found: %1. Click one to use it.").arg(found_->count()));
    }
    validate();
}

void ConnectDialog::accept() {
    if (!problem().isEmpty()) {
        return;
    }
    scan_->stop();
    if (!emulated_->isChecked()) {
        remember_robot(normalized_nxt_address(address_->text()));
    }
    QDialog::accept();
}

}  // namespace legofeup::ui
