#include "legofeup/core/lesson_filters_config.hpp"

namespace legofeup {

const char* to_string(Localisation localisation) {
    switch (localisation) {
        case Localisation::Walls:
            return "walls";
        case Localisation::Beacons:
            return "beacons";
        case Localisation::GyroFusion:
            return "gyro_fusion";
        case Localisation::Compass:
            return "compass";
        case Localisation::Laser:
            return "laser";
    }
    return "unknown";
}

const char* to_string(FilterKind kind) {
    switch (kind) {
        case FilterKind::Ekf:
            return "ekf";
        case FilterKind::Ukf:
            return "ukf";
        case FilterKind::Pf:
            return "pf";
    }
    return "unknown";
}

std::optional<Localisation> localisation_from_string(std::string_view text) {
    for (const Localisation value :
         {Localisation::Walls, Localisation::Beacons, Localisation::GyroFusion,
          Localisation::Compass, Localisation::Laser}) {
        if (text == to_string(value)) {
            return value;
        }
    }
    return std::nullopt;
}

std::optional<FilterKind> filter_kind_from_string(std::string_view text) {
    for (const FilterKind value : {FilterKind::Ekf, FilterKind::Ukf, FilterKind::Pf}) {
        if (text == to_string(value)) {
            return value;
        }
    }
    return std::nullopt;
}

}  // namespace legofeup
