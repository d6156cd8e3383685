#include "legofeup/core/filter_base.hpp"

namespace legofeup {

const char* to_string(StepStatus status) {
    switch (status) {
        case StepStatus::Applied:
            return "applied";
        case StepStatus::NotAttempted:
            return "not attempted";
        case StepStatus::RejectedNonFinite:
            return "rejected: non-finite value";
        case StepStatus::RejectedSingular:
            return "rejected: innovation covariance not positive definite";
        case StepStatus::RejectedByGate:
            return "rejected by the Mahalanobis gate";
        case StepStatus::AppliedLinearised:
            return "applied linearised (no sigma points: predicted as the EKF)";
    }
    return "unknown";
}

}  // namespace legofeup
