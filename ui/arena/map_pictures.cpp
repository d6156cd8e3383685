#include "legofeup/ui/arena/map_pictures.hpp"

#include "legofeup/ui/arena/map_image.hpp"

namespace legofeup::ui {

void MapPictures::update(const ArenaScene& scene, const ArenaColors& colors) {
    const QRgb colour = colors.map_occupied.rgba();
    if (scene.map.get() != world_source_ || colour != colour_) {
        world_source_ = scene.map.get();
        world_map_ =
            scene.map ? map_image(*scene.map, {colors.map_occupied, colors.map_unknown}) : QImage();
    }
    if (scene.filter_map.get() != filter_source_ || colour != colour_) {
        filter_source_ = scene.filter_map.get();
        // The filter's own (outdated) map over the world's: its walls tinted, half seen.
        filter_map_ = scene.filter_map
                          ? map_image(*scene.filter_map, {colors.filter_map, Qt::transparent})
                          : QImage();
    }
    colour_ = colour;
}

}  // namespace legofeup::ui
