#include "legofeup/ui/arena/arena_layers.hpp"

#include <algorithm>

namespace legofeup::ui {

// Each lesson's layers, one file each.
const ArenaLayer& ir_rays_layer();      // ir_rays_layer.cpp: the LegoFeup lesson (paper 000)
const ArenaLayer& beacons_layer();      // beacons_layer.cpp: bearing-only beacons (paper 002)
const ArenaLayer& laser_scans_layer();  // laser_scans_layer.cpp: the laser lesson (paper 001)
// particle_cloud_layer.cpp: the particle filter's cloud, whatever the robot measures (it draws
// nothing for a Gaussian filter's run).
const ArenaLayer& particle_cloud_layer();

const ArenaLayerRegistry& built_in_arena_layers() {
    static const ArenaLayerRegistry registry{
        {Localisation::Walls, {&particle_cloud_layer(), &ir_rays_layer()}},
        {Localisation::Beacons, {&particle_cloud_layer(), &beacons_layer()}},
        {Localisation::GyroFusion, {}},  // its sensors have nothing to show in the arena
        {Localisation::Compass, {&particle_cloud_layer()}},
        {Localisation::Laser, {&particle_cloud_layer(), &laser_scans_layer()}},
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
