# File ▸ Re-filter recorded run…: a run log replayed with new Q and R, overlaid on the old.
list(APPEND LEGOFEUP_UI_SOURCES
    refilter/refilter_dialog.cpp
    refilter/refilter_job.cpp
    refilter/refilter_metrics.cpp
    refilter/refilter_plots.cpp
    include/legofeup/ui/refilter/refilter_dialog.hpp  # Q_OBJECT: listed for AUTOMOC
    include/legofeup/ui/refilter/refilter_plots.hpp  # Q_OBJECT: listed for AUTOMOC
)
