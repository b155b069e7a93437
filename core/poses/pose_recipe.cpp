#include "core/poses/pose_recipe.h"

#include <cmath>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/hand/pose_set_generator.h"
#include "core/io/json_checked.h"
#include "core/io/pose_set_tsv.h"
#include "core/io/pose_source.h"

namespace lmc {
namespace fs = std::filesystem;

namespace {

constexpr const char* kRecipeFormat = "lmc-pose-recipe";

fs::path recipe_path(const fs::path& base_dir, const std::string& text) {
  const fs::path p(text);
  return p.is_absolute() ? p : base_dir / p;
}

// N frames taken evenly across `from` (thinned or repeated), labels with them.
void append_evenly(const PoseSet& from, int n, PoseSet& to) {
  const int size = from.size();
  for (int k = 0; k < n && size > 0; ++k) {
    const auto j = static_cast<size_t>(
        std::min<long long>(size - 1, static_cast<long long>(std::floor((k + 0.5) * static_cast<double>(size) / n))));
    to.frames.push_back(from.frames[j]);
    to.labels.push_back(j < from.labels.size() ? from.labels[j] : PoseLabel{});
  }
}

}  // namespace

namespace {

PoseRecipe recipe_from_json(const nlohmann::json& j, const std::string& source, const fs::path& base_dir) {
  const JsonReader root(j, source);
  root.require_object();
  root.only_keys({"format", "format_version", "frames", "parts", "monte_carlo", "description"});
  if (root.string("format") != kRecipeFormat) root.at("format").fail(std::string("expected \"") + kRecipeFormat + "\"");
  if (root.at("format_version").integer() != 1) root.at("format_version").fail("only version 1 is known");
  PoseRecipe r;
  r.source = source;
  if (root.has("frames")) {
    const int frames = root.at("frames").integer();
    if (frames < 1 || frames > 10'000'000) root.at("frames").fail("must be 1 … 10,000,000");
    r.frames = frames;
  }
  if (root.has("monte_carlo")) {
    const JsonReader mc = root.at("monte_carlo");
    mc.require_object();
    mc.only_keys({"share", "seed", "hand"});
    r.monte_carlo_share = mc.number_or("share", 0.0);
    if (!(r.monte_carlo_share >= 0.0 && r.monte_carlo_share <= 1.0)) mc.at("share").fail("must be 0 … 1");
    if (mc.has("seed")) {
      const double seed = mc.number("seed");
      if (seed < 0 || seed != std::floor(seed) || seed > 9.0e15) mc.at("seed").fail("must be a whole number ≥ 0");
      r.monte_carlo_seed = static_cast<std::uint64_t>(seed);
    }
    if (mc.has("hand")) r.monte_carlo_hand = recipe_path(base_dir, mc.string("hand")).string();
  }
  if (root.has("parts")) {
    const JsonReader parts = root.at("parts");
    for (size_t i = 0; i < parts.array_size(); ++i) {
      const JsonReader p = parts.at(i);
      p.require_object();
      p.only_keys({"from", "poses", "source", "trials", "every", "weight", "layout"});
      PoseRecipePart part;
      part.weight = p.number_or("weight", 1.0);
      if (!(part.weight > 0.0)) p.at("weight").fail("must be greater than 0");
      if (p.has("from") == p.has("poses")) p.fail("give either \"from\" (recordings) or \"poses\" (a pose-set file)");
      if (p.has("poses")) {
        part.poses = recipe_path(base_dir, p.string("poses"));
      } else {
        const JsonReader from = p.at("from");
        if (from.json().is_string()) {
          part.from.push_back(recipe_path(base_dir, from.string()));
        } else {
          for (size_t k = 0; k < from.array_size(); ++k)
            part.from.push_back(recipe_path(base_dir, from.at(k).string()));
        }
        if (part.from.empty()) from.fail("names no recording");
        try {
          parse_recorded_pose_source(p.string_or("source", "fused"), part.options);
        } catch (const Error& e) {
          p.at("source").fail(e.what());
        }
        part.options.trials_glob = p.string_or("trials", "");
        if (p.has("every")) {
          part.options.every = p.at("every").integer();
          if (part.options.every < 1) p.at("every").fail("must be 1 or more");
        }
        if (p.has("layout")) part.options.layout = p.string("layout");
      }
      r.parts.push_back(std::move(part));
    }
  }
  if (r.parts.empty() && r.monte_carlo_share < 1.0)
    root.fail("no parts: give recordings in \"parts\" or set \"monte_carlo\": {\"share\": 1}");
  if (!r.parts.empty() && r.monte_carlo_share >= 1.0)
    root.at("monte_carlo").at("share").fail("is 1, so the recorded parts would get no frames");
  return r;
}

}  // namespace

PoseRecipe parse_pose_recipe(const std::string& text, const std::string& source, const fs::path& base_dir) {
  return recipe_from_json(parse_json_text(text, source), source, base_dir);
}

PoseRecipe load_pose_recipe(const fs::path& path) {
  return recipe_from_json(read_json_file(path), path.string(), path.parent_path());
}

PoseSet build_pose_set(const PoseRecipe& recipe, std::vector<std::string>* notes) {
  std::vector<PoseSet> parts;
  double weight_sum = 0;
  int recorded = 0;
  for (const auto& part : recipe.parts) {
    if (part.poses) {
      parts.push_back(load_pose_set(*part.poses));
    } else {
      RecordedPoseSet rec = pose_set_from_recordings(part.from, part.options);
      if (notes) notes->insert(notes->end(), rec.skipped.begin(), rec.skipped.end());
      parts.push_back(std::move(rec.set));
    }
    weight_sum += part.weight;
    recorded += parts.back().size();
  }
  const double share = recipe.monte_carlo_share;
  int total = 0;
  if (recipe.frames) {
    total = *recipe.frames;
  } else {
    total = parts.empty() ? kDefaultMonteCarloFrames
                          : static_cast<int>(std::lround(recorded / std::max(1e-9, 1.0 - share)));
  }
  const int mc_frames = static_cast<int>(std::lround(total * share));
  const int recorded_frames = total - mc_frames;

  PoseSet out;
  out.frames.reserve(static_cast<size_t>(total));
  out.labels.reserve(static_cast<size_t>(total));
  std::string what;
  int given = 0;
  double weight_before = 0;
  for (size_t i = 0; i < parts.size(); ++i) {
    // Cumulative rounding, so the parts' counts add up to recorded_frames exactly.
    weight_before += recipe.parts[i].weight;
    const int upto = static_cast<int>(std::lround(recorded_frames * weight_before / weight_sum));
    const int n = upto - given;
    given = upto;
    append_evenly(parts[i], n, out);
    const std::string from = recipe.parts[i].poses ? recipe.parts[i].poses->string() : parts[i].description;
    out.provenance.push_back("part " + std::to_string(i + 1) + " (weight " + format_fixed(recipe.parts[i].weight, 2) +
                             "): " + std::to_string(n) + " frames taken evenly from " +
                             std::to_string(parts[i].size()) + " of " + from);
    for (const auto& line : parts[i].provenance) out.provenance.push_back("  " + line);
    what += (what.empty() ? "" : " + ") + std::to_string(n) + " recorded";
  }
  if (mc_frames > 0) {
    PoseSetSettings s;
    s.frames = mc_frames;
    s.seed = recipe.monte_carlo_seed;
    const PoseSet mc = generate_pose_set(load_hand_model(recipe.monte_carlo_hand), s);
    out.frames.insert(out.frames.end(), mc.frames.begin(), mc.frames.end());
    out.labels.insert(out.labels.end(), mc.labels.begin(), mc.labels.end());
    out.provenance.push_back("Monte Carlo share " + format_fixed(100.0 * share, 1) + " %: " + mc.description +
                             (recipe.monte_carlo_hand ? " hand=" + *recipe.monte_carlo_hand : ""));
    what += (what.empty() ? "" : " + ") + std::to_string(mc_frames) + " Monte Carlo";
  }
  for (size_t j = 0; j < out.frames.size(); ++j) out.frames[j].frame_id = static_cast<std::int64_t>(j);
  out.description = "recipe " + recipe.source + " (" + what + " frames)";
  return out;
}

PoseSet load_pose_spec(const std::string& spec, int frames, std::uint64_t seed,
                       const std::optional<std::string>& hand_path, std::vector<std::string>* notes) {
  if (spec != "mc" && fs::path(spec).extension() == ".json") return build_pose_set(load_pose_recipe(spec), notes);
  return load_poses(spec, frames, seed, hand_path);
}

}  // namespace lmc
