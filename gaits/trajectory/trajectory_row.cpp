#include "gaits/trajectory/trajectory_row.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "dynamics/joint_coordinates.hpp"

namespace gaitopt::gaits {
namespace {

using config::ConfigError;

/// q and dq are redundant with theta and dtheta (Mu 2.41); a file whose copies disagree by more
/// than this was edited by hand or written for another convention [rad, rad/s].
constexpr double kDerivedTolerance = 1e-9;

/// Reads the fields of one data row in column order, naming file, line and column on error.
class RowParser {
 public:
  RowParser(const RowSource& source, const std::vector<std::string>& names,
            std::vector<std::string_view> fields)
      : source_(source), names_(names), fields_(std::move(fields)) {
    if (fields_.size() != names_.size())
      throw ConfigError(
          source_.path, source_.key_prefix, source_.line,
          fmt::format("expected {} comma-separated fields (one per header column), found {}{}",
                      names_.size(), fields_.size(),
                      fields_.size() < names_.size() ? " (truncated line?)" : ""));
  }

  double number() {
    const double value = current();
    ++next_;
    return value;
  }

  Eigen::VectorXd numbers(int n) {
    Eigen::VectorXd v(n);
    for (int i = 0; i < n; ++i) v(i) = number();
    return v;
  }

  Phase phase() {
    const std::string_view text = fields_[next_];
    if (text != "SSP" && text != "DSP")
      fail(fmt::format("unknown phase {}, expected SSP or DSP", quotedField(text)));
    ++next_;
    return text == "SSP" ? Phase::kSsp : Phase::kDsp;
  }

  /// Reads redundant columns that must equal `expected` (e.g. q = M theta).
  void derived(const VecD& expected, const char* relation) {
    for (int i = 0; i < expected.size(); ++i) {
      const double value = current();
      if (std::abs(value - expected(i)) > kDerivedTolerance)
        fail(fmt::format("{:.17g} disagrees with {} = {:.17g} (tolerance {})", value, relation,
                         expected(i), kDerivedTolerance));
      ++next_;
    }
  }

  /// Throws a ConfigError about the current column.
  [[noreturn]] void fail(const std::string& message) const {
    throw ConfigError(source_.path, source_.key_prefix + names_[next_], source_.line, message);
  }

 private:
  /// The current field as a finite number; from_chars is locale-independent and strict (no
  /// spaces, no leading '+', the whole field must be consumed).
  double current() const {
    const std::string_view text = fields_[next_];
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size())
      fail(fmt::format("expected a number, found {}", quotedField(text)));
    if (!std::isfinite(value)) fail(fmt::format("non-finite value {}", quotedField(text)));
    return value;
  }

  const RowSource& source_;
  const std::vector<std::string>& names_;
  std::vector<std::string_view> fields_;
  size_t next_ = 0;
};

Row readRow(RowParser& row, const dynamics::Model& model,
            const std::vector<PhysicalJoint>& joints) {
  const int n = model.nLinks();
  Row out;
  Knot& k = out.knot;
  k.t = row.number();
  k.phase = row.phase();
  k.theta = row.numbers(n);
  k.dtheta = row.numbers(n);
  k.ddtheta = row.numbers(n);
  const VecD q = dynamics::toJoint(VecD(k.theta)), dq = dynamics::toJoint(VecD(k.dtheta));
  row.derived(q, "M theta (Mu 2.41)");
  row.derived(dq, "M dtheta (Mu 2.41)");
  k.tau = row.numbers(n);
  k.force_stance = row.numbers(2);
  k.force_swing = row.numbers(2);
  row.numbers(3);  // zmp_x, hip_x, hip_y: outputs for controllers, recomputed when writing
  out.swing_x = row.number();
  row.numbers(3);  // swing_y, com_x, com_y
  row.derived(physicalValues(joints, q, true), "the physical joint of q");
  row.derived(physicalValues(joints, dq, false), "the physical joint rate of dq");
  row.derived(physicalValues(joints, VecD(k.tau), false), "the physical joint torque of tau");
  return out;
}

}  // namespace

/// A field quoted for an error message, shortened so a corrupt line cannot flood the terminal.
std::string quotedField(std::string_view text) {
  constexpr size_t kMax = 40;
  return text.size() <= kMax ? fmt::format("'{}'", text)
                             : fmt::format("'{}...'", text.substr(0, kMax - 3));
}

Row parseRow(const RowSource& source, const std::vector<std::string>& names,
             std::vector<std::string_view> fields, const dynamics::Model& model,
             const std::vector<PhysicalJoint>& joints) {
  RowParser parser(source, names, std::move(fields));
  return readRow(parser, model, joints);
}

}  // namespace gaitopt::gaits
