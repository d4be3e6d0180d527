#pragma once
// Settings tables of `agglo calibrate` (docs/calibrate.md): the fit ([calibrate]), the parameters it
// varies ([[parameter]], one or two) and the observables it matches ([[target]], one or more). The
// target cases are ordinary vcrit/breakup case files; the parameter keys are any of their keys.
#include "agglo/core/settings.hpp"

namespace agglo::settings {

inline constexpr std::string_view kCalibrateCommands = "calibrate";

struct CalibrateSettings {
  struct Fit {
    Table t{"calibrate", kCalibrateCommands, "how the parameters are fitted"};
    Integer grid_points{t, {"calibrate.grid_points", "", "points per parameter of the first map of the box"}, 7, 3, 101};
    Integer refine_rounds{t, {"calibrate.refine_rounds", "", "maps zoomed on the set that meets every target"}, 1, 0,
                          10};
    Integer refine_points{t, {"calibrate.refine_points", "", "points per parameter of each zoomed map"}, 5, 2, 101};
    Integer fine_points{t, {"calibrate.fine_points", "", "points per parameter where the surrogate is searched"}, 101,
                        11, 2001};
    Real span{t, {"calibrate.span", "", "fraction of the mapped points in each local regression of the surrogate"},
              0.3, Range::open_closed(0.0, 1.0)};
    Real smoothing{t,
                   {"calibrate.smoothing", "",
                    "smallest width the surrogate follows, in spacings of the first map (narrower bumps are "
                    "averaged out or rejected)"},
                   1.5, Range::open_closed(0.0, 10.0)};
    Integer robustness_iterations{
        t, {"calibrate.robustness_iterations", "", "bisquare reweightings that reject runs off the trend"}, 2, 0, 10};
    Text case_overrides{t,
                        {"calibrate.case_overrides", "",
                         "key=value assignments (separated by ';') applied to every target case, e.g. "
                         "agglomerate.orientation=\"edge_along\""},
                        ""};
    Bool check{t, {"calibrate.check", "", "run the observables again at the best fit"}, true};
    Choice predict{t,
                   {"calibrate.predict", "",
                    "where the [[prediction]] observables are run: range = best fit and the extreme points of the "
                    "set that meets every target; best = best fit only; none = skipped"},
                   "range",
                   {"range", "best", "none"}};
    Bool widths{t,
                {"calibrate.widths", "",
                 "at the best fit also run each target's break-up curve: the width of p(v) is the observable's "
                 "uncertainty"},
                false};
  } fit;

  struct Parameter {
    Table t{"parameter", kCalibrateCommands, "a parameter the fit varies (one or two tables)", true};
    Text key{t, {"parameter.key", "", "dotted key of the target cases, e.g. material.restitution"}, std::nullopt};
    Real lower{t, {"parameter.lower", "", "lower end of the range (unit of the key)"}, std::nullopt, Range::any()};
    Real upper{t, {"parameter.upper", "", "upper end of the range (unit of the key)"}, std::nullopt, Range::any()};
    Choice scale{t, {"parameter.scale", "", "spacing of the maps over the range"}, "linear", {"linear", "log"}};
  } parameter;

  struct Target {
    Table t{"target", kCalibrateCommands, "an observable to match (one or more tables)", true};
    Text case_file{t, {"target.case", "", "vcrit/breakup case file, relative to the calibration file"}, std::nullopt};
    Choice observable{t,
                      {"target.observable", "",
                       "v_crit: single-run critical speed (vcrit); v50: speed of break-up probability 0.5 (breakup)"},
                      "v_crit",
                      {"v_crit", "v50"}};
    Real value{t, {"target.value", "m/s", "target value of the observable"}, std::nullopt, Range::positive()};
    Real tolerance{t, {"target.tolerance", "m/s", "how far from the target value still meets it"}, std::nullopt,
                   Range::positive()};
  } target;

  struct Prediction {
    Table t{"prediction", kCalibrateCommands,
            "an observable predicted at the best fit and over the set that meets every target (optional tables)", true};
    Text case_file{t, {"prediction.case", "", "vcrit/breakup case file, relative to the calibration file"},
                   std::nullopt};
    Choice observable{t, {"prediction.observable", "", "v_crit or v50, as for a target"}, "v_crit", {"v_crit", "v50"}};
  } prediction;

  std::vector<const Table*> tables() const { return {&fit.t, &parameter.t, &target.t, &prediction.t}; }
};

const CalibrateSettings& calibrate_settings();

}  // namespace agglo::settings
