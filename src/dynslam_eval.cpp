// dynslam-eval: APE / RPE of an estimated trajectory against a reference, with the definitions
// of evo (github.com/MichaelGrupp/evo) so that figures can be compared with published ones;
// `bars` draws a table of such figures (e.g. per scenario and variant) as a bar chart.
// Exit codes: 0 success, 1 bad data (unreadable file, nothing to associate, ...), 2 usage.
#include <dynslam/core/AtomicFile.h>
#include <dynslam/core/CommandLine.h>
#include <dynslam/core/JsonWriter.h>
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/evaluation/Alignment.h>
#include <dynslam/evaluation/Ape.h>
#include <dynslam/evaluation/Association.h>
#include <dynslam/evaluation/EvaluationError.h>
#include <dynslam/evaluation/Plot.h>
#include <dynslam/evaluation/Rpe.h>
#include <dynslam/evaluation/Statistics.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using dynslam::core::TrajectoryFormat;
namespace ev = dynslam::evaluation;

const char* const kUsage = R"(usage:
  dynslam-eval ape REF EST [options]
  dynslam-eval rpe REF EST [options] [rpe options]
  dynslam-eval bars TABLE.tsv OUT.png [--title T] [--value-label L]
  dynslam-eval -h | --help

ape / rpe compute evo's absolute / relative pose error of the estimate EST against the
reference REF (github.com/MichaelGrupp/evo, same definitions, so figures compare with published
ones) and print the files, the pairs, the alignment and rmse, mean, median, std, min, max, sse.
Poses are associated by timestamp (tum, euroc) like evo, or by index when a file is kitti (the
files must then hold as many poses).

options (ape and rpe):
  --format tum|kitti|euroc   format of both files (default tum)
  --ref-format F             format of REF only (e.g. euroc ground truth with a tum estimate)
  --est-format F             format of EST only
  --align none|se3|sim3      Umeyama alignment of EST to REF before the errors (default none)
  --align-origin             move EST so that its first pose is REF's first pose (after --align)
  --t-max-diff S             max. time difference of associated poses, seconds (default 0.01)
  --t-offset S               constant offset added to EST's timestamps, seconds (default 0)
  --pose-relation R          trans|rot|full|angle_deg|angle_rad (default trans)
  --json FILE                write {"rmse", "mean", "median", "std", "min", "max", "sse"}
  --plot FILE.png            write a top view of both paths and the error over time
  --plot-plane xy|xz|yz      coordinates of the top view (default xy)
rpe options:
  --delta N                  distance between the poses of a pair (default 1)
  --delta-unit f|m           N in frames or in metres of travelled path (default f)
  --all-pairs                use every pair at distance N, not only consecutive ones
  --delta-tol X              relative tolerance of --all-pairs with metres (default 0.1)
  --pairs-from-reference     choose the pairs on REF's path (default: on EST's, as evo does)
bars options:
  --title T                  the chart's title
  --value-label L            the value axis' label
  -h, --help                 print this text and exit

bars draws a grouped bar chart of TABLE.tsv (tab-separated; '#' lines are comments): a header
row "GROUP-AXIS<TAB>SERIES1<TAB>SERIES2...", then one row per group, "GROUP<TAB>VALUE...";
a value "-" or empty draws no bar. It prints "bars  G groups x S series -> OUT.png".

Exit codes: 0 success, 1 bad data (unreadable file, nothing to associate, a malformed table),
2 usage (unknown flag, a flag of another command, a bad value).
)";

using dynslam::core::UsageError;

struct Options {
  std::string command, ref_path, est_path;
  TrajectoryFormat ref_format = TrajectoryFormat::Tum, est_format = TrajectoryFormat::Tum;
  ev::AlignmentMode align = ev::AlignmentMode::None;
  bool align_origin = false;
  double t_max_diff = 0.01, t_offset = 0.0;
  ev::PoseRelation relation = ev::PoseRelation::TranslationPart;
  std::string json_path, plot_path;
  ev::PlotPlane plot_plane = ev::PlotPlane::XY;
  ev::RpeOptions rpe;
};

/// Parses a flag's value with `parse` when the flag is given, turning std::invalid_argument
/// into a usage error that names the flag.
template <typename T, typename Parse>
void parseChoice(const dynslam::core::CommandLine& cl, const std::string& flag, T& target,
                 Parse parse) {
  if (!cl.has(flag)) return;
  try {
    target = parse(cl.valueOr(flag, ""));
  } catch (const std::invalid_argument& e) {
    throw UsageError("flag " + flag + ": " + e.what());
  }
}

/// The flags of ape and rpe (none applies to bars).
const char* const kTrajectoryFlags[] = {
    "--format",     "--ref-format",   "--est-format",    "--align",
    "--t-max-diff", "--t-offset",     "--pose-relation", "--json",
    "--plot",       "--plot-plane",   "--delta",         "--delta-unit",
    "--delta-tol",  "--align-origin", "--all-pairs",     "--pairs-from-reference"};

Options parseArguments(const dynslam::core::CommandLine& cl) {
  Options o;
  const auto& positional = cl.positional();
  if (positional.size() != 3)
    throw UsageError("expected a command and two files (ape|rpe REF EST), got " +
                     std::to_string(positional.size()) + " arguments");
  o.command = positional[0];
  if (o.command != "ape" && o.command != "rpe")
    throw UsageError("unknown command '" + o.command + "' (expected ape, rpe or bars)");
  for (const char* flag : {"--title", "--value-label"})
    if (cl.has(flag)) throw UsageError(std::string("flag ") + flag + " only applies to bars");
  o.ref_path = positional[1];
  o.est_path = positional[2];

  TrajectoryFormat both = TrajectoryFormat::Tum;
  parseChoice(cl, "--format", both, dynslam::core::parseTrajectoryFormat);
  o.ref_format = o.est_format = both;
  parseChoice(cl, "--ref-format", o.ref_format, dynslam::core::parseTrajectoryFormat);
  parseChoice(cl, "--est-format", o.est_format, dynslam::core::parseTrajectoryFormat);
  parseChoice(cl, "--align", o.align, ev::parseAlignmentMode);
  parseChoice(cl, "--pose-relation", o.relation, ev::parsePoseRelation);
  parseChoice(cl, "--plot-plane", o.plot_plane, ev::parsePlotPlane);
  parseChoice(cl, "--delta-unit", o.rpe.delta_unit, ev::parseDeltaUnit);
  o.align_origin = cl.has("--align-origin");
  o.t_max_diff = cl.optionalDouble("--t-max-diff").value_or(o.t_max_diff);
  o.t_offset = cl.optionalDouble("--t-offset").value_or(o.t_offset);
  o.json_path = cl.valueOr("--json", "");
  o.plot_path = cl.valueOr("--plot", "");
  o.rpe.delta = cl.optionalDouble("--delta").value_or(o.rpe.delta);
  o.rpe.rel_delta_tol = cl.optionalDouble("--delta-tol").value_or(o.rpe.rel_delta_tol);
  o.rpe.all_pairs = cl.has("--all-pairs");
  o.rpe.pairs_from_reference = cl.has("--pairs-from-reference");
  o.rpe.relation = o.relation;

  if (o.command == "ape") {
    for (const char* flag :
         {"--delta", "--delta-unit", "--all-pairs", "--delta-tol", "--pairs-from-reference"})
      if (cl.has(flag)) throw UsageError(std::string("flag ") + flag + " only applies to rpe");
  }
  if (o.t_max_diff < 0.0) throw UsageError("flag --t-max-diff must be >= 0");
  if (!(o.rpe.delta > 0.0)) throw UsageError("flag --delta must be > 0");
  if (o.rpe.delta_unit == ev::DeltaUnit::Frames && o.rpe.delta != std::floor(o.rpe.delta))
    throw UsageError("flag --delta must be a whole number of frames with --delta-unit f");
  if (o.rpe.rel_delta_tol < 0.0) throw UsageError("flag --delta-tol must be >= 0");
  return o;
}

/// The table of `dynslam-eval bars` (see kUsage); throws EvaluationError naming the file and
/// line of a row with the wrong number of cells or a value that is not a number.
ev::BarChartInput readBarTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ev::EvaluationError("cannot read bar table '" + path + "'");
  ev::BarChartInput chart;
  std::string line;
  bool header = true;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::size_t start = 0;
    for (std::size_t tab; (tab = line.find('\t', start)) != std::string::npos; start = tab + 1)
      cells.push_back(line.substr(start, tab - start));
    cells.push_back(line.substr(start));
    const std::string where = path + ":" + std::to_string(number);
    if (header) {
      if (cells.size() < 2) throw ev::EvaluationError(where + ": the header names no series");
      chart.series.assign(cells.begin() + 1, cells.end());
      header = false;
      continue;
    }
    if (cells.size() != chart.series.size() + 1)
      throw ev::EvaluationError(where + ": " + std::to_string(cells.size()) + " cells, expected " +
                                std::to_string(chart.series.size() + 1));
    chart.groups.push_back(cells[0]);
    auto& row = chart.values.emplace_back();
    for (std::size_t k = 1; k < cells.size(); ++k) {
      if (cells[k].empty() || cells[k] == "-") {
        row.push_back(std::nan(""));
        continue;
      }
      std::size_t used = 0;
      double v = 0;
      try {
        v = std::stod(cells[k], &used);
      } catch (const std::exception&) {
      }
      if (used != cells[k].size())
        throw ev::EvaluationError(where + ": '" + cells[k] + "' is not a number");
      row.push_back(v);
    }
  }
  if (chart.groups.empty()) throw ev::EvaluationError("bar table '" + path + "' has no row");
  return chart;
}

/// Shortest text that reads back as the same double (what Python prints).
std::string fullPrecision(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("nan");
}

const char* formatName(TrajectoryFormat f) {
  return f == TrajectoryFormat::Tum ? "tum" : f == TrajectoryFormat::Kitti ? "kitti" : "euroc";
}

void printAlignment(const ev::AlignmentResult& a) {
  std::cout << "alignment   " << ev::toString(a.mode) << (a.origin_aligned ? " + origin" : "")
            << '\n';
  if (a.mode != ev::AlignmentMode::None) {
    const auto& r = a.umeyama.rotation;
    for (int row = 0; row < 3; ++row)
      std::cout << (row == 0 ? "rotation    " : "            ") << fullPrecision(r(row, 0)) << ' '
                << fullPrecision(r(row, 1)) << ' ' << fullPrecision(r(row, 2)) << '\n';
    const auto& t = a.umeyama.translation;
    std::cout << "translation " << fullPrecision(t.x()) << ' ' << fullPrecision(t.y()) << ' '
              << fullPrecision(t.z()) << '\n'
              << "scale       " << fullPrecision(a.umeyama.scale) << '\n';
  }
  if (a.origin_aligned) {
    const Eigen::Matrix4d m = a.origin_transform.matrix();
    for (int row = 0; row < 3; ++row)
      std::cout << (row == 0 ? "origin      " : "            ") << fullPrecision(m(row, 0)) << ' '
                << fullPrecision(m(row, 1)) << ' ' << fullPrecision(m(row, 2)) << ' '
                << fullPrecision(m(row, 3)) << '\n';
  }
}

void writeJson(const std::string& path, const ev::ErrorStatistics& s) {
  dynslam::core::AtomicTextFile file(path);
  dynslam::core::JsonWriter json(file.stream());
  json.beginObject()
      .member("rmse", s.rmse)
      .member("mean", s.mean)
      .member("median", s.median)
      .member("std", s.std)
      .member("min", s.min)
      .member("max", s.max)
      .member("sse", s.sse)
      .endObject();
  try {
    file.commit();
  } catch (const std::runtime_error& e) {
    throw ev::EvaluationError(std::string("JSON file: ") + e.what());
  }
}

/// dynslam-eval bars TABLE.tsv OUT.png: the table as a grouped bar chart.
int runBars(const dynslam::core::CommandLine& cl) {
  const auto& positional = cl.positional();
  if (positional.size() != 3)
    throw UsageError("expected bars TABLE.tsv OUT.png, got " + std::to_string(positional.size()) +
                     " arguments");
  for (const char* flag : kTrajectoryFlags)
    if (cl.has(flag))
      throw UsageError(std::string("flag ") + flag + " only applies to ape and rpe");
  ev::BarChartInput chart = readBarTable(positional[1]);
  chart.title = cl.valueOr("--title", "");
  chart.value_label = cl.valueOr("--value-label", "");
  ev::writeBarChartPng(positional[2], chart);
  std::cout << "bars        " << chart.groups.size() << " groups x " << chart.series.size()
            << " series -> " << positional[2] << '\n';
  return 0;
}

/// Reads both files and pairs their poses (printing both and the pairing).
ev::AssociatedTrajectories readAndAssociate(const Options& o, bool by_index) {
  const auto ref_full = dynslam::core::readTrajectory(o.ref_path, o.ref_format);
  const auto est_full = dynslam::core::readTrajectory(o.est_path, o.est_format);
  std::cout << "reference   " << o.ref_path << " (" << formatName(o.ref_format) << ", "
            << ref_full.size() << " poses)\n"
            << "estimate    " << o.est_path << " (" << formatName(o.est_format) << ", "
            << est_full.size() << " poses)\n";
  ev::AssociatedTrajectories pairs =
      by_index ? ev::associateByIndex(ref_full, est_full)
               : ev::associateByTime(ref_full, est_full, o.t_max_diff, o.t_offset);
  if (by_index)
    std::cout << "pairs       " << pairs.first.size() << " (paired by index)\n";
  else
    std::cout << "pairs       " << pairs.first.size() << " of max. " << pairs.max_pairs
              << " (max. time diff " << o.t_max_diff << " s, offset " << o.t_offset << " s)\n";
  return pairs;
}

/// The errors (APE per pose or RPE per pair) and when each occurs, in s since EST's first pose.
struct PoseErrors {
  std::vector<double> errors, times;
};

PoseErrors computeErrors(const Options& o, const dynslam::core::Trajectory& ref,
                         const dynslam::core::Trajectory& est) {
  PoseErrors e;
  const double t0 = est.front().t;
  if (o.command == "ape") {
    e.errors = ev::computeApe(ref, est, o.relation);
    for (const auto& p : est) e.times.push_back(p.t - t0);
    return e;
  }
  const ev::RpeResult rpe = ev::computeRpe(ref, est, o.rpe);
  e.errors = rpe.errors;
  for (const auto& [i, j] : rpe.pairs) e.times.push_back(est[j].t - t0);
  std::cout << "rpe pairs   " << rpe.pairs.size() << " (delta " << o.rpe.delta
            << (o.rpe.delta_unit == ev::DeltaUnit::Frames ? " frames" : " m")
            << (o.rpe.all_pairs ? ", all pairs" : ", consecutive pairs") << ")\n";
  return e;
}

void printStatistics(const ev::ErrorStatistics& s) {
  const std::pair<const char*, double> rows[] = {
      {"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median}, {"std", s.std},
      {"min", s.min},   {"max", s.max},   {"sse", s.sse}};
  for (const auto& [name, value] : rows) {
    std::string padded = name;
    padded.resize(7, ' ');
    std::cout << padded << fullPrecision(value) << '\n';
  }
}

void writePlot(const Options& o, const ev::AssociatedTrajectories& pairs, const PoseErrors& e,
               bool by_index) {
  const std::string unit = ev::unitOf(o.relation);
  const std::string metric = o.command == "ape" ? "APE" : "RPE";
  ev::PlotInput plot;
  plot.title = metric + " w.r.t. " + ev::describe(o.relation) + ", alignment " +
               ev::toString(o.align) + (o.align_origin ? " + origin" : "") + ": " +
               o.est_path.substr(o.est_path.find_last_of('/') + 1);
  plot.reference = pairs.first;
  plot.estimate = pairs.second;
  plot.errors = e.errors;
  plot.error_times = e.times;
  plot.error_label = metric + (unit.empty() ? "" : " (" + unit + ")");
  plot.time_label = by_index ? "pose index" : "t - t0 (s)";
  plot.plane = o.plot_plane;
  ev::writePlotPng(o.plot_path, plot);
}

int run(const Options& o) {
  // KITTI files carry no time, so any pair with one is paired by index (evo's kitti mode).
  const bool by_index =
      o.ref_format == TrajectoryFormat::Kitti || o.est_format == TrajectoryFormat::Kitti;
  ev::AssociatedTrajectories pairs = readAndAssociate(o, by_index);
  printAlignment(ev::alignTrajectory(pairs.first, pairs.second, o.align, o.align_origin));
  const PoseErrors errors = computeErrors(o, pairs.first, pairs.second);
  const std::string unit = ev::unitOf(o.relation);
  std::cout << (o.command == "ape" ? "APE" : "RPE") << " w.r.t. " << ev::describe(o.relation)
            << (unit.empty() ? "" : " (" + unit + ")") << '\n';
  const ev::ErrorStatistics s = ev::computeStatistics(errors.errors);
  printStatistics(s);
  if (!o.json_path.empty()) writeJson(o.json_path, s);
  if (!o.plot_path.empty()) writePlot(o, pairs, errors, by_index);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return dynslam::core::runProgram("dynslam-eval", [&] {
    dynslam::core::CommandLine cl(
        {"--format", "--ref-format", "--est-format", "--align", "--t-max-diff", "--t-offset",
         "--pose-relation", "--json", "--plot", "--plot-plane", "--delta", "--delta-unit",
         "--delta-tol", "--title", "--value-label"},
        {"--align-origin", "--all-pairs", "--pairs-from-reference"}, {}, 3);
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    if (!cl.positional().empty() && cl.positional()[0] == "bars") return runBars(cl);
    return run(parseArguments(cl));
  });
}
