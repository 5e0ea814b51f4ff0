// contest: the best engine of a machine within a contest's limits, and the Pareto front of range
// against the axle's load (contest.hpp, docs/machines.md).
#include <cmath>
#include <iostream>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/app/contest_record.hpp"
#include "trebuchet/app/text_input.hpp"

namespace trebuchet::verify {

int run_contest(const Options& o) {
  ContestRequest request;
  request.machine = o.design.machine.value_or(MachineKind::hinged);
  if (!o.design.m) throw Error(ErrorKind::usage, "contest needs the projectile's mass; give {{m}}, e.g. {{m}} 0.5kg");
  request.projectile_mass = *o.design.m;
  request.material = material_of(o.design, Material{});
  if (o.beam_per_m && o.design.D) throw Error(ErrorKind::usage, "--mb-per-m and {{D}} both give the beam's mass per metre; give one");
  if (!o.beam_per_m && !o.design.D)
    throw Error(ErrorKind::usage,
                "contest needs the beam: its diameter {{D}} (of the wood, --wood-density) or its mass per metre --mb-per-m, e.g. --mb-per-m 1.5");
  request.beam_mass_per_length = o.beam_per_m ? *o.beam_per_m
                                              : request.material.wood_density * M_PI / 4 * *o.design.D * *o.design.D;  // eq:BeamMass per metre
  request.theta_i_deg = o.design.theta_i_deg.value_or(standard_theta_i_deg);
  if (!(request.theta_i_deg > 0 && request.theta_i_deg < 90))
    throw Error(ErrorKind::bad_number,
                "{{theta_i_deg}} = " + format_significant(request.theta_i_deg, 6) + ": the initial beam angle must lie between 0 and 90 degrees");
  request.settings = settings_of(o);
  request.efficiency = o.efficiency;
  request.settings.criterion.release = o.efficiency ? Release::efficiency : Release::range;  // released where the objective peaks
  request.limits = o.limits;
  request.box_width = o.design.box_width, request.box_height = o.design.box_height;
  request.min_clearance = o.min_clearance;
  if (!o.plot.empty() && o.pareto == 0) throw Error(ErrorKind::usage, "--plot draws the Pareto front; give --pareto 20 (its points) too");
  const ContestEngine best = contest_optimum(request);
  const std::vector<ContestEngine> front = o.pareto > 0 ? pareto_front(request, o.pareto) : std::vector<ContestEngine>{};
  if (!o.plot.empty()) write_picture_folder(o.plot, pareto_pictures(front, request), {"pareto.gp"});
  if (o.format == Format::json)
    std::cout << pretty_json(contest_json(best, request, front));
  else
    std::cout << contest_table(best, request, front, o.units);
  return exit_success;
}

}  // namespace trebuchet::verify
