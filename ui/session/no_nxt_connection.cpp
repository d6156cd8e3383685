// A build without the NXT (LEGOFEUP_WITH_NXT=OFF): no brick to take, real or emulated.
#include <QObject>

#include "legofeup/ui/session/nxt_connection.hpp"

namespace legofeup::ui {

bool nxt_supported() {
    return false;
}

NxtConnection prepare_nxt_connection(const LinkChoice& /*choice*/,
                                     const lessons::RobotProfile* /*profile*/,
                                     const lessons::RunConfig& /*config*/) {
    NxtConnection connection;
    connection.problem = QObject::tr(
        "This build has no NXT support (built with LEGOFEUP_WITH_NXT=OFF): choose a simulator");
    return connection;
}

}  // namespace legofeup::ui
