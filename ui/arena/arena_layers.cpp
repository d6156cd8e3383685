#include "legofeup/ui/arena/arena_layers.hpp"

#include <algorithm>

namespace legofeup::ui {

// Each lesson's layers, one file each.
const ArenaLayer& ir_rays_layer();      // ir_rays_layer.cpp: the LegoFeup lesson (paper 000)
const ArenaLayer& beacons_layer();      // beacons_layer.cpp: bearing-only beacons (paper 002)
const ArenaLayer& laser_scans_layer();  // laser_scans_layer.cpp: the laser lesson (paper 001)

const ArenaLayerRegistry& built_in_arena_layers() {
    static const ArenaLayerRegistry registry{
        {Localisation::Walls, {&ir_rays_layer()}},
        {Localisation::Beacons, {&beacons_layer()}},
        {Localisation::GyroFusion, {}},  // its sensors have nothing to show in the arena
        {Localisation::Compass, {}},
        {Localisation::Laser, {&laser_scans_layer()}},
    };
    return registry;
}

std::span<const ArenaLayer* const> layers_for(const ArenaLayerRegistry& registry,
                                              Localisation localisation) {
    const auto entry = std::find_if(
        registry.begin(), registry.end(),
        [localisation](const ArenaLessonLayers& e) { return e.localisation == localisation; });
    if (entry == registry.end()) {
        return {};
    }
    return entry->layers;
}

Localisation shown_localisation(const RunHistory& history) {
    if (!history.empty()) {
        return history.latest().snapshot.localisation;
    }
    const ArenaScene& scene = history.scene();
    if (scene.laser.active) {
        return Localisation::Laser;
    }
    return scene.beacons.empty() ? Localisation::Walls : Localisation::Beacons;
}

}  // namespace legofeup::ui
