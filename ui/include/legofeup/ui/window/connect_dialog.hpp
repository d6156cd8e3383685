#pragma once
// "Connect to an NXT": the brick's address (checked as it is typed, with the link's own
// words under the field), the robots connected to before, a Bluetooth scan where BlueZ runs,
// the relay program, a robot profile, and rehearsing with an emulated brick (docs/nxt.md).

#include <QDialog>

#include "legofeup/ui/session/session.hpp"

class QCheckBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QListWidgetItem;
class QPushButton;

namespace legofeup::ui {

class BluetoothScan;

class ConnectDialog : public QDialog {
    Q_OBJECT

  public:
    /// Starts from `current` (its NXT fields) and the persisted recent robots.
    explicit ConnectDialog(const LinkChoice& current, QWidget* parent = nullptr);
    ~ConnectDialog() override;

    /// The choice as entered: `current` with kind Nxt and the dialog's NXT fields (the
    /// address normalised: a bare XX:XX:… becomes bt:XX:XX:…).
    LinkChoice choice() const;
    /// Why the entry cannot be used (the address's problem), or an empty string.
    QString problem() const;

    QLineEdit* addressField() const { return address_; }
    QLabel* addressMessage() const { return address_message_; }
    QListWidget* recentList() const { return recent_; }
    QPushButton* removeRecentButton() const { return remove_recent_; }
    QPushButton* scanButton() const { return scan_button_; }
    QListWidget* foundList() const { return found_; }
    QLabel* scanMessage() const { return scan_message_; }
    QCheckBox* relayBox() const { return relay_; }
    QLineEdit* profileField() const { return profile_; }
    QCheckBox* emulatedBox() const { return emulated_; }
    QPushButton* okButton() const;

  public slots:
    /// Remembers the address among the recent robots (not an emulated brick) and closes.
    void accept() override;
    void startScan();

  private:
    void validate();
    void useAddress(const QString& address);
    void removeRecent();
    void chooseProfile();
    void deviceFound(const QString& address, const QString& name);
    void scanFinished(const QString& problem);

    LinkChoice current_;
    QLineEdit* address_ = nullptr;
    QLabel* address_message_ = nullptr;
    QListWidget* recent_ = nullptr;
    QPushButton* remove_recent_ = nullptr;
    QPushButton* scan_button_ = nullptr;
    QListWidget* found_ = nullptr;
    QLabel* scan_message_ = nullptr;
    QCheckBox* relay_ = nullptr;
    QLineEdit* profile_ = nullptr;
    QCheckBox* emulated_ = nullptr;
    QDialogButtonBox* buttons_ = nullptr;
    BluetoothScan* scan_ = nullptr;
};

}  // namespace legofeup::ui
