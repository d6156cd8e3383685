# plots: the plots panel (one QCustomPlot per quantity), its series table, look and export.
list(APPEND LEGOFEUP_UI_SOURCES
    plots/plot_series.cpp
    plots/plot_style.cpp
    plots/plot_export.cpp
    plots/plots_panel.cpp
    include/legofeup/ui/plots/plots_panel.hpp
)
