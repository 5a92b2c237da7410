#include "engine/seeding/classification_report.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

namespace garment {
namespace {

bool in(SeedClass value, std::initializer_list<SeedClass> set) {
  for (SeedClass member : set)
    if (member == value) return true;
  return false;
}

std::string group_name(const LabelledPattern& pattern, int group) {
  std::string name;
  for (int piece : pattern.graph.groups[group])
    name += (name.empty() ? "" : "+") + pattern.piece_names[piece];
  return name;
}

int top_ranked(const PieceClassification& result, std::initializer_list<SeedClass> classes) {
  int best = 0;
  double best_score = -1.0;
  for (int g = 0; g < static_cast<int>(result.groups.size()); ++g) {
    double score = 0.0;
    for (SeedClass seed_class : classes)
      score += result.probability(g, seed_class);
    if (score > best_score) {
      best_score = score;
      best = g;
    }
  }
  return best;
}

}  // namespace

double ClassificationReport::precision(SeedClass seed_class) const {
  const int c = static_cast<int>(seed_class);
  const int predicted = confusion.col(c).sum();
  return predicted > 0 ? static_cast<double>(confusion(c, c)) / predicted
                       : std::numeric_limits<double>::quiet_NaN();
}

double ClassificationReport::recall(SeedClass seed_class) const {
  const int c = static_cast<int>(seed_class);
  const int actual = confusion.row(c).sum();
  return actual > 0 ? static_cast<double>(confusion(c, c)) / actual
                    : std::numeric_limits<double>::quiet_NaN();
}

double ClassificationReport::accuracy() const {
  const int total = confusion.sum();
  return total > 0 ? static_cast<double>(confusion.trace()) / total : 0.0;
}

ClassificationReport evaluate_classifier(const PieceClassifier& classifier,
                                         const std::vector<LabelledPattern>& patterns) {
  ClassificationReport report;
  for (const LabelledPattern& pattern : patterns) {
    ++report.patterns;
    const PieceClassification result = classifier.classify(pattern.graph);
    const int group_count = static_cast<int>(pattern.group_labels.size());
    bool has_neck_or_waist = false, has_chest = false, has_front = false, has_back = false;
    for (int g = 0; g < group_count; ++g) {
      const SeedClass truth = pattern.group_labels[g];
      ++report.confusion(static_cast<int>(truth), static_cast<int>(result.group_class(g)));
      has_neck_or_waist = has_neck_or_waist || in(truth, {SeedClass::Neck, SeedClass::Waist});
      has_front = has_front || truth == SeedClass::FrontChest;
      has_back = has_back || truth == SeedClass::BackChest;
    }
    has_chest = has_front || has_back;
    const std::string file = pattern.file.filename().string();
    const auto describe = [&](int g) {
      return group_name(pattern, g) + ": " + seed_class_name(pattern.group_labels[g]) + " -> " +
             seed_class_name(result.group_class(g));
    };

    const std::initializer_list<SeedClass> neck_or_waist = {SeedClass::Neck, SeedClass::Waist};
    const int neck_or_waist_top = top_ranked(result, neck_or_waist);
    const bool neck_or_waist_claimed = in(result.group_class(neck_or_waist_top), neck_or_waist);
    if (has_neck_or_waist) {
      ++report.neck_or_waist.patterns;
      if (in(pattern.group_labels[neck_or_waist_top], neck_or_waist) && neck_or_waist_claimed)
        ++report.neck_or_waist.found;
      else
        report.misses.push_back(file + ": neck/waist missed (" + describe(neck_or_waist_top) + ")");
    } else {
      ++report.patterns_without_neck_or_waist;
      if (neck_or_waist_claimed) {
        ++report.neck_or_waist_false_alarms;
        report.misses.push_back(file + ": neck/waist false alarm (" + describe(neck_or_waist_top) +
                                ")");
      }
    }

    const std::initializer_list<SeedClass> chests = {SeedClass::FrontChest, SeedClass::BackChest};
    if (has_chest) {
      ++report.chest.patterns;
      const int top = top_ranked(result, chests);
      if (in(pattern.group_labels[top], chests) && in(result.group_class(top), chests))
        ++report.chest.found;
      else
        report.misses.push_back(file + ": chest missed (" + describe(top) + ")");
    }
    if (has_front && has_back) {
      ++report.both_chests.patterns;
      bool both = true;
      for (SeedClass side : chests) {
        const int top = top_ranked(result, {side});
        both = both && pattern.group_labels[top] == side && result.group_class(top) == side;
      }
      if (both) ++report.both_chests.found;
    }
  }
  return report;
}

std::string format_classification_report(const ClassificationReport& report) {
  std::string text;
  char line[256];
  std::snprintf(line, sizeof line, "%d patterns, %d seed pieces, accuracy %.3f\n\n",
                report.patterns, report.confusion.sum(), report.accuracy());
  text += line;
  std::snprintf(line, sizeof line, "%-13s %9s %9s %8s\n", "class", "precision", "recall",
                "support");
  text += line;
  for (int c = 0; c < kSeedClassCount; ++c) {
    const SeedClass seed_class = static_cast<SeedClass>(c);
    std::snprintf(line, sizeof line, "%-13s %9.3f %9.3f %8d\n", seed_class_name(seed_class).c_str(),
                  report.precision(seed_class), report.recall(seed_class),
                  report.confusion.row(c).sum());
    text += line;
  }
  text += "\nconfusion (rows: true class, columns: predicted)\n";
  std::snprintf(line, sizeof line, "%-13s", "");
  text += line;
  for (int c = 0; c < kSeedClassCount; ++c) {
    std::snprintf(line, sizeof line, " %8.8s", std::string(kSeedClassNames[c]).c_str());
    text += line;
  }
  text += "\n";
  for (int r = 0; r < kSeedClassCount; ++r) {
    std::snprintf(line, sizeof line, "%-13s", std::string(kSeedClassNames[r]).c_str());
    text += line;
    for (int c = 0; c < kSeedClassCount; ++c) {
      std::snprintf(line, sizeof line, " %8d", report.confusion(r, c));
      text += line;
    }
    text += "\n";
  }
  const auto rate = [&](const char* name, const DetectionRate& detection) {
    std::snprintf(line, sizeof line, "%-22s %4d / %4d = %5.1f %%\n", name, detection.found,
                  detection.patterns, 100.0 * detection.rate());
    text += line;
  };
  text += "\ndetection (patterns that have the piece)\n";
  rate("neck-or-waist found", report.neck_or_waist);
  rate("chest found", report.chest);
  rate("both chests found", report.both_chests);
  std::snprintf(line, sizeof line, "%-22s %4d / %4d\n", "neck/waist false alarm",
                report.neck_or_waist_false_alarms, report.patterns_without_neck_or_waist);
  text += line;
  if (!report.misses.empty()) {
    text += "\nmisses\n";
    for (const std::string& miss : report.misses)
      text += "  " + miss + "\n";
  }
  return text;
}

std::string classification_report_json(const ClassificationReport& report) {
  const auto number = [](double value) {
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
  };
  nlohmann::json root;
  root["patterns"] = report.patterns;
  root["accuracy"] = report.accuracy();
  for (int c = 0; c < kSeedClassCount; ++c) {
    const SeedClass seed_class = static_cast<SeedClass>(c);
    root["classes"][seed_class_name(seed_class)] = {
        {"precision", number(report.precision(seed_class))},
        {"recall", number(report.recall(seed_class))},
        {"support", report.confusion.row(c).sum()}};
  }
  root["class_order"] = std::vector<std::string>(kSeedClassNames.begin(), kSeedClassNames.end());
  root["confusion"] = nlohmann::json::array();
  for (int r = 0; r < kSeedClassCount; ++r) {
    std::vector<int> row(kSeedClassCount);
    for (int c = 0; c < kSeedClassCount; ++c)
      row[c] = report.confusion(r, c);
    root["confusion"].push_back(row);
  }
  const auto detection = [](const DetectionRate& rate) {
    return nlohmann::json{
        {"patterns", rate.patterns}, {"found", rate.found}, {"rate", rate.rate()}};
  };
  root["detection"] = {{"neck_or_waist", detection(report.neck_or_waist)},
                       {"chest", detection(report.chest)},
                       {"both_chests", detection(report.both_chests)},
                       {"neck_or_waist_false_alarms",
                        {{"patterns", report.patterns_without_neck_or_waist},
                         {"false_alarms", report.neck_or_waist_false_alarms}}}};
  root["misses"] = report.misses;
  return root.dump(2);
}

}  // namespace garment
