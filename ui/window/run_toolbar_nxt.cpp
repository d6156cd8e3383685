// The toolbar's NXT: the connect dialog, in a build with the NXT (LEGOFEUP_WITH_NXT).
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/connect_dialog.hpp"
#include "legofeup/ui/window/run_toolbar.hpp"

namespace legofeup::ui {

ConnectDialog* RunToolBar::openConnectDialog() {
    auto* dialog = new ConnectDialog(session_.linkChoice(), window());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        session_.setLinkChoice(dialog->choice());
        showLinkFields();
    });
    connect(dialog, &QDialog::rejected, this, [this] { showLinkFields(); });
    dialog->open();
    return dialog;
}

}  // namespace legofeup::ui
