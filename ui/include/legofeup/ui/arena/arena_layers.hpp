#pragma once
// Which layers the arena draws for which run: an explicit list, one entry per localisation
// (as lessons::built_in_lessons() lists the lessons; no self-registration). A new lesson's
// drawing is a layer in its own file and one entry here (arena_layers.cpp).

#include <span>
#include <vector>

#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/ui/arena/arena_layer.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

/// The layers drawn for runs that localise with `localisation`, in drawing order.
struct ArenaLessonLayers {
    Localisation localisation = Localisation::Walls;
    std::vector<const ArenaLayer*> layers;
};
using ArenaLayerRegistry = std::vector<ArenaLessonLayers>;

/// The layers that ship with the program: every localisation, even one that draws nothing
/// of its own.
const ArenaLayerRegistry& built_in_arena_layers();

/// The layers `registry` lists for `localisation` (none when it has no entry).
std::span<const ArenaLayer* const> layers_for(const ArenaLayerRegistry& registry,
                                              Localisation localisation);

/// How the run in `history` localises: the latest sample says; before the first one, a
/// scene with the laser is the laser lesson's, one with beacons theirs, any other the walls'.
Localisation shown_localisation(const RunHistory& history);

}  // namespace legofeup::ui
