// trebuchet._trebuchet: each request of trebuchet::api (api.hpp) as a function of JSON text to
// JSON text, read as the programs read a JSON file. The package python/trebuchet turns Python
// values into the text and the answer into dicts and NumPy arrays. A refusal comes back as the
// api's error object ({"error", "kind", "names"}), which the package raises. The interpreter's
// lock is released for the call: notebooks can run several on threads.
#include <pybind11/pybind11.h>

#include <string>

#include "trebuchet/app/api/api.hpp"
#include "version.hpp"

PYBIND11_MODULE(_trebuchet, module) {
  module.doc() = "trebuchet's library as JSON requests (trebuchet/app/api/api.hpp); use the package trebuchet";
  module.attr("version") = trebuchet::build_version();  // the project's, PEP 440 (0.1.0)
  module.attr("commit") = trebuchet::build_commit();  // git describe of the source it is built from
  namespace py = pybind11;
  const auto bind = [&](const char* name, trebuchet::api::Request request, const char* doc) {
    module.def(
        name, [request](const std::string& text) { return trebuchet::api::answer_text(request, text, "docs/python.md"); }, py::arg("request"), doc,
        py::call_guard<py::gil_scoped_release>());
  };
  bind("design", trebuchet::api::design, "the calculator's design: JSON text in, JSON text out");
  bind("shot", trebuchet::api::shot, "one shot of a design");
  bind("optimize", trebuchet::api::optimize, "the ab-initio optimum");
  bind("sweep", trebuchet::api::sweep, "a what-if sweep: one value of a design over a range");
  bind("complete", trebuchet::api::complete, "the completion of an attested engine");
  bind("compare", trebuchet::api::compare, "one engine built as each machine, side by side");
  bind("contest", trebuchet::api::contest, "the best engine of a machine within a contest's limits");
  bind("monte_carlo", trebuchet::api::monte_carlo, "a Monte Carlo run");
  bind("fields", trebuchet::api::fields, "the table of inputs: every key with its aliases, dimension, unit, default and help");
}
