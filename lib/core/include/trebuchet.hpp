// The core of trebuchet: the physics of the paper, the calculator, the optimizer, the completion,
// the derivation of tab:CPNC and Monte Carlo, with no files, formats or flags. Everything in
// it is reached through this one header; the application layer is trebuchet/app.hpp.
#pragma once

#include "trebuchet/air.hpp"
#include "trebuchet/angles.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/capacity.hpp"
#include "trebuchet/capacity_fit.hpp"
#include "trebuchet/calibration.hpp"
#include "trebuchet/completion.hpp"
#include "trebuchet/design.hpp"
#include "trebuchet/dynamics.hpp"
#include "trebuchet/engine.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/integrator.hpp"
#include "trebuchet/material.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/parallel.hpp"
#include "trebuchet/quality.hpp"
#include "trebuchet/quantity.hpp"
#include "trebuchet/scaling_table.hpp"
#include "trebuchet/shot.hpp"
#include "trebuchet/sweep.hpp"
#include "trebuchet/table_derivation.hpp"
#include "trebuchet/uncertainty.hpp"
#include "trebuchet/verification.hpp"
