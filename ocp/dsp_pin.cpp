#include "ocp/dsp_pin.hpp"

#include <fmt/format.h>

#include "ocp/autodiff_constraint.hpp"

namespace gaitopt::ocp {

void addDspPin(Nlp& nlp, const dynamics::Model& model, const Phase& phase, double step_length) {
  const int n = model.nLinks();
  const PointLayout& l = phase.point;
  addLink(nlp, phase.name() + "_pin_start", 2, phase.indices(0, l.motion()), 2 * n,
          TipAcceleration{&model});
  for (int k = 1; k <= phase.layout.segments; ++k) {
    const int p = k * phase.layout.pointsPerSegment();
    addLink(nlp, fmt::format("{}_pin_{}", phase.name(), k), 4,
            concat(phase.indices(p, l.q), phase.indices(p, l.v)), n,
            PinnedTip{&model, step_length});
  }
}

}  // namespace gaitopt::ocp
