// A build without the NXT (LEGOFEUP_WITH_NXT=OFF) has no connect dialog: the toolbar offers no
// NXT and hides its connect action, so nothing opens one.
#include "legofeup/ui/window/run_toolbar.hpp"

namespace legofeup::ui {

ConnectDialog* RunToolBar::openConnectDialog() {
    return nullptr;
}

}  // namespace legofeup::ui
