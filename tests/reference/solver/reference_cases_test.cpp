// Every folder of reference_cases/ with a case.json runs with lmgc-solve (its DATBOX/COMMAND.DAT
// gives the run, case.json's optional "flags" are added to the command line), and each expected
// quantity of case.json holds within its stated tolerance. The quantities are computed from
// lmgc-solve's output files only: POSTPRO/BODY_<n>.DAT (BODY TRACKING rows, state-and-outputs.md
// §4: 2D, 10 columns: time, the centre x, y and angle θ, the displacements X(1:3) from the reference
// position, the velocities vx, vy, ω; 3D, 13 columns: time, the centre x, y, z, the displacements
// X(1:3), the velocities vx, vy, vz and ω(1:3) in the body's principal axes) and
// OUTBOX/Vloc_Rloc.LAST (rln/H = normal impulse / time step = mean normal force of the last step,
// state-and-outputs.md §1.4). The vertical is y in 2D and z in 3D; a direction or vector of case.json
// has 2 components for a 2D case and 3 for a 3D one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "grammar/vloc_rloc/parser.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;
using Table = std::vector<std::vector<double>>;

// Columns of a BODY TRACKING row: the time, then from kX the centre, from kDx the displacement and
// from kVx the velocity, `dimension` values each (the 2D rows carry θ, X(3) and ω after x, y; the 3D
// rows ω(1:3) after v).
constexpr std::size_t kTime = 0, kX = 1, kDx = 4, kVx = 7, kOmega2D = 9;
constexpr std::size_t kColumns2D = 10, kColumns3D = 13;

// The BODY TRACKING rows of one body and whether they are 2D or 3D rows.
struct Track {
  Table rows;
  std::size_t dimension = 2;                                   // 2 (RBDY2 rows) or 3 (RBDY3 rows)
  std::size_t vertical() const { return kX + dimension - 1; }  // column of y (2D) or z (3D)
};

Table read_table(const fs::path& path) {
  Table rows;
  std::istringstream in(read_file(path));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream values(line);
    std::vector<double> row;
    double v;
    while (values >> v) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

// The BODY TRACKING rows of one body, read once per case.
class Tracks {
 public:
  explicit Tracks(fs::path postpro) : postpro_(std::move(postpro)) {}
  const Track& of(int body) {
    auto it = tracks_.find(body);
    if (it != tracks_.end()) return it->second;
    char name[32];
    std::snprintf(name, sizeof name, "BODY_%07d.DAT", body);
    Track track;
    track.rows = read_table(postpro_ / name);
    EXPECT_FALSE(track.rows.empty()) << name << " is missing or empty (is the body tracked in POSTPRO.DAT?)";
    if (!track.rows.empty()) {
      const std::size_t columns = track.rows.front().size();
      EXPECT_TRUE(columns == kColumns2D || columns == kColumns3D) << name << ": " << columns << " columns";
      track.dimension = columns == kColumns3D ? 3 : 2;
      for (const auto& row : track.rows) EXPECT_EQ(row.size(), columns) << name;
      // Keep only complete rows so that every column index below is valid.
      std::erase_if(track.rows, [columns](const auto& row) { return row.size() != columns; });
    }
    return tracks_.emplace(body, std::move(track)).first->second;
  }

 private:
  fs::path postpro_;
  std::map<int, Track> tracks_;
};

// Σ row[first + k] d[k]: the component along d of the vector starting at column `first`.
double along(const Track& track, const std::vector<double>& row, std::size_t first,
             const std::vector<double>& d) {
  EXPECT_EQ(d.size(), track.dimension) << "case.json's vector must have one component per dimension";
  double sum = 0.0;
  for (std::size_t k = 0; k < track.dimension && k < d.size(); ++k) sum += row[first + k] * d[k];
  return sum;
}

// Euclidean norm of the `dimension` values starting at column `first`.
double norm_of(const Track& track, const std::vector<double>& row, std::size_t first) {
  double sum = 0.0;
  for (std::size_t k = 0; k < track.dimension; ++k) sum += row[first + k] * row[first + k];
  return std::sqrt(sum);
}

// Heights of the local maxima of the body centre's vertical coordinate (y in 2D, z in 3D), minus
// `offset`.
std::vector<double> apex_heights(const Track& track, double offset) {
  const Table& rows = track.rows;
  const std::size_t c = track.vertical();
  std::vector<double> apexes;
  for (std::size_t i = 1; i + 1 < rows.size(); ++i)
    if (rows[i][c] >= rows[i - 1][c] && rows[i][c] > rows[i + 1][c]) apexes.push_back(rows[i][c] - offset);
  return apexes;
}

// Least-squares slope of the velocity along `direction` over the rows with from <= t <= to.
double acceleration_along(const Track& track, const std::vector<double>& direction, double from, double to) {
  double n = 0, st = 0, sv = 0, stt = 0, stv = 0;
  for (const auto& row : track.rows) {
    const double t = row[kTime];
    if (t < from || t > to) continue;
    const double v = along(track, row, kVx, direction);
    n += 1;
    st += t;
    sv += v;
    stt += t * t;
    stv += t * v;
  }
  EXPECT_GE(n, 2) << "no rows between t = " << from << " and t = " << to;
  return (n * stv - st * sv) / (n * stt - st * st);
}

// The row whose time is nearest to t.
const std::vector<double>& row_at(const Table& rows, double t) {
  static const std::vector<double> kNone(kColumns3D, std::nan(""));
  if (rows.empty()) return kNone;
  auto best = std::min_element(rows.begin(), rows.end(), [t](const auto& a, const auto& b) {
    return std::fabs(a[kTime] - t) < std::fabs(b[kTime] - t);
  });
  return *best;
}

const grammar::Real* labelled(const grammar::VlocRlocInteraction& c, const std::string& label) {
  for (const auto& vector : c.vectors)
    for (std::size_t k = 0; k < vector.labels.size() && k < vector.values.size(); ++k)
      if (vector.labels[k] == label) return &vector.values[k];
  return nullptr;
}

// Each quantity kind: computes it from the run's outputs and compares with case.json.
void check_quantity(const nlohmann::json& expected, const fs::path& dir, Tracks& tracks) {
  const std::string quantity = expected.at("quantity");
  SCOPED_TRACE(quantity);
  ASSERT_FALSE(expected.at("source").get<std::string>().empty());
  ASSERT_FALSE(expected.at("tolerance_reason").get<std::string>().empty());
  const double tolerance = expected.at("tolerance");
  const auto body = [&] { return expected.at("body").get<int>(); };
  if (quantity == "apex_heights") {
    const auto apexes = apex_heights(tracks.of(body()), expected.at("offset"));
    const auto values = expected.at("values").get<std::vector<double>>();
    ASSERT_GE(apexes.size(), values.size());
    for (std::size_t n = 0; n < values.size(); ++n)
      EXPECT_NEAR(apexes[n], values[n], tolerance) << "apex " << n + 1;
  } else if (quantity == "slope_acceleration") {
    // Acceleration along a unit direction, fitted on the tracked velocity over [from, to].
    const double a = acceleration_along(tracks.of(body()), expected.at("direction"), expected.at("from"),
                                        expected.at("to"));
    EXPECT_NEAR(a, expected.at("value").get<double>(), tolerance);
  } else if (quantity == "displacement_below") {
    // |(X1, X2)| (2D) or |(X1, X2, X3)| (3D) stays below the tolerance at every tracked step up to
    // `until`.
    const Track& track = tracks.of(body());
    const Table& rows = track.rows;
    const double until = expected.at("until");
    ASSERT_FALSE(rows.empty());
    ASSERT_GE(rows.back()[kTime], until - 1e-12) << "the run stops before t = " << until;
    double largest = 0.0;
    for (const auto& row : rows)
      if (row[kTime] <= until + 1e-12) largest = std::max(largest, norm_of(track, row, kDx));
    EXPECT_LE(largest, tolerance) << "largest displacement up to t = " << until;
  } else if (quantity == "rolling") {
    // Rolling without slip: v·d = ω r at every tracked step from `from` on (d: unit direction in
    // which a positive ω makes the disk advance, i.e. along the ground with the ground below). 2D
    // rows only: a 3D row's ω is in the body's principal axes, whose orientation it does not carry.
    const Track& track = tracks.of(body());
    ASSERT_EQ(track.dimension, 2u) << "\"rolling\" is computed from 2D BODY TRACKING rows only";
    const Table& rows = track.rows;
    const auto d = expected.at("direction").get<std::vector<double>>();
    const double r = expected.at("radius"), from = expected.at("from");
    double largest = 0.0;
    std::size_t counted = 0;
    for (const auto& row : rows)
      if (row[kTime] >= from) {
        largest = std::max(largest, std::fabs(along(track, row, kVx, d) - row[kOmega2D] * r));
        ++counted;
      }
    ASSERT_GT(counted, 0u);
    EXPECT_LE(largest, tolerance) << "largest slip velocity |v·d − ω r|";
  } else if (quantity == "column_reactions") {
    // Normal force of every contact of OUTBOX/Vloc_Rloc.LAST (rln/H); values[k] is the force under
    // body first_body + k (the upper body: the larger body number) — the sum over the points of a
    // polyhedron pair (PRPRx, PRPLx), whose split between points is statically indeterminate.
    grammar::DiagnosticSink sink;
    const fs::path path = dir / "OUTBOX" / "Vloc_Rloc.LAST";
    const auto file = grammar::parse_vloc_rloc(grammar::SourceText(path.string(), read_file(path)), sink);
    ASSERT_FALSE(sink.has_errors()) << path;
    const auto values = expected.at("values").get<std::vector<double>>();
    const int first = expected.at("first_body");
    ASSERT_GE(file.interactions.size(), values.size());
    std::vector<int> seen(values.size(), 0);
    std::vector<double> force(values.size(), 0.0);
    bool polyhedra = false;
    for (const auto& c : file.interactions) {
      const bool polyhedron = c.type.value == "PRPRx" || c.type.value == "PRPLx";
      polyhedra = polyhedra || polyhedron;
      ASSERT_TRUE(polyhedron || c.type.value == "DKDKx" || c.type.value == "DKJCx" ||
                  c.type.value == "SPSPx" || c.type.value == "SPPLx")
          << c.type.value;
      // Integers: candidate body, its contactor, [CDVER,] antagonist body, ...
      const std::size_t antagonist_at = polyhedron ? 3 : 2;
      ASSERT_GT(c.integers.size(), antagonist_at);
      const auto upper = std::max(c.integers[0].value, c.integers[antagonist_at].value);
      const auto k = static_cast<std::size_t>(upper - first);
      ASSERT_LT(k, values.size()) << "contact with body " << upper;
      ++seen[k];
      const grammar::Real* rn = labelled(c, "rln/H");
      ASSERT_NE(rn, nullptr);
      force[k] += rn->value;
      if (!polyhedron) {
        EXPECT_NEAR(rn->value, values[k], tolerance) << "contact under body " << upper;
      }
    }
    for (std::size_t k = 0; k < seen.size(); ++k) {
      if (polyhedra) {
        EXPECT_GE(seen[k], 1) << "contact under body " << first + static_cast<int>(k);
      } else {
        EXPECT_EQ(seen[k], 1) << "contact under body " << first + static_cast<int>(k);
      }
      EXPECT_NEAR(force[k], values[k], tolerance) << "force under body " << first + static_cast<int>(k);
    }
  } else if (quantity == "velocities_after") {
    // (vx, vy) (2D) or (vx, vy, vz) (3D) of each listed body at every tracked step from `after` on.
    const double after = expected.at("after");
    for (const auto& item : expected.at("bodies")) {
      const int b = item.at("body");
      const auto v = item.at("velocity").get<std::vector<double>>();
      const Track& track = tracks.of(b);
      ASSERT_EQ(v.size(), track.dimension) << "body " << b << ": one velocity component per dimension";
      std::size_t counted = 0;
      for (const auto& row : track.rows)
        if (row[kTime] >= after) {
          ++counted;
          bool off = false;
          for (std::size_t k = 0; k < v.size(); ++k) {
            EXPECT_NEAR(row[kVx + k], v[k], tolerance)
                << "body " << b << " v" << k + 1 << " at t = " << row[kTime];
            off = off || std::fabs(row[kVx + k] - v[k]) > tolerance;
          }
          if (off) break;
        }
      EXPECT_GT(counted, 0u) << "body " << b << ": no row after t = " << after;
    }
  } else if (quantity == "positions_at") {
    // Centre (x, y) (2D) or (x, y, z) (3D) of each listed body at the tracked step nearest to `time`.
    const double time = expected.at("time");
    for (const auto& item : expected.at("bodies")) {
      const int b = item.at("body");
      const auto x = item.at("position").get<std::vector<double>>();
      const Track& track = tracks.of(b);
      ASSERT_EQ(x.size(), track.dimension) << "body " << b << ": one position component per dimension";
      const auto& row = row_at(track.rows, time);
      ASSERT_NEAR(row[kTime], time, 1e-9) << "body " << b << ": no row at t = " << time;
      for (std::size_t k = 0; k < x.size(); ++k)
        EXPECT_NEAR(row[kX + k], x[k], tolerance) << "body " << b << " x" << k + 1;
    }
  } else {
    ADD_FAILURE() << "case.json names a quantity this test does not compute: " << quantity;
  }
}

std::vector<fs::path> reference_cases() {
  std::vector<fs::path> cases;
  for (const auto& entry : fs::directory_iterator(fs::path(LMGC_SOURCE_DIR) / "reference_cases"))
    if (fs::exists(entry.path() / "case.json")) cases.push_back(entry.path());
  std::sort(cases.begin(), cases.end());
  return cases;
}

TEST(ReferenceCases, EveryExpectedQuantityHoldsWithinItsTolerance) {
  const auto cases = reference_cases();
  ASSERT_FALSE(cases.empty());
  for (const fs::path& source : cases) {
    SCOPED_TRACE(source.filename().string());
    const auto spec = nlohmann::json::parse(read_file(source / "case.json"));
    const fs::path dir = scratch_dir("reference_" + source.filename().string());
    fs::copy(source / "DATBOX", dir / "DATBOX", fs::copy_options::recursive);
    std::string flags;
    if (spec.contains("flags"))
      for (const auto& flag : spec.at("flags")) flags += " '" + flag.get<std::string>() + "'";
    ASSERT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --quiet" + flags).exit_code, 0);
    ASSERT_FALSE(spec.at("expected").empty());
    Tracks tracks(dir / "POSTPRO");
    for (const auto& expected : spec.at("expected")) check_quantity(expected, dir, tracks);
  }
}

}  // namespace
}  // namespace lmgc::test
