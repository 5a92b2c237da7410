#include <chrono>
#include <cstdio>
#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "engine/core/error.h"
#include "engine/pattern/pattern_files.h"
#include "engine/seeding/classification_report.h"
#include "engine/seeding/classifier_training.h"
#include "engine/seeding/classifier_weights.h"
#include "engine/seeding/piece_classifier.h"
#include "output_plan.h"

namespace garment::cli {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::vector<std::filesystem::path> dataset_files(const std::string& folder) {
  if (!std::filesystem::is_directory(folder))
    throw InputError(folder + ": not a folder of pattern files");
  std::vector<std::filesystem::path> files = pattern_files(folder);
  if (files.empty()) throw InputError(folder + ": no pattern files (*.json)");
  return files;
}

std::filesystem::path regions_path(const CommandLine& line, const std::string& folder) {
  return line.value("--regions")
      .value_or(
          (std::filesystem::path(folder).lexically_normal().parent_path() / "panel_regions.json")
              .string());
}

std::vector<std::filesystem::path> split_files(const std::vector<std::filesystem::path>& files,
                                               const std::string& split) {
  if (split != "held-out" && split != "training" && split != "all")
    throw UsageError("--split must be held-out, training or all");
  std::vector<std::filesystem::path> selected;
  for (std::size_t i = 0; i < files.size(); ++i)
    if (split == "all" || (split == "held-out") == is_held_out(i)) selected.push_back(files[i]);
  return selected;
}

}  // namespace

int train_classifier_command(const std::vector<std::string>& args) {
  const CommandLine line(args, {}, {"-o", "--regions", "--epochs", "--ensemble", "--seed"});
  const std::string folder = line.only_positional("data folder");
  const auto output = line.value("-o");
  if (!output) throw UsageError("-o WEIGHTS.json is required");
  TrainingOptions options;
  options.epochs = line.integer("--epochs", options.epochs);
  if (options.epochs < 1) throw UsageError("--epochs must be at least 1");
  options.ensemble = line.integer("--ensemble", options.ensemble);
  if (options.ensemble < 1) throw UsageError("--ensemble must be at least 1");
  options.seed = static_cast<std::uint64_t>(line.integer("--seed", static_cast<int>(options.seed)));

  // The folder is read as a whole: weights written into it would be read as a pattern next time.
  OutputPlan plan;
  plan.input_folder("DATA_DIR", folder);
  plan.input("--regions", regions_path(line, folder));
  plan.output("-o", *output);
  plan.check();
  const std::vector<std::filesystem::path> files = dataset_files(folder);
  const PanelLabeller labeller = PanelLabeller::load(regions_path(line, folder));
  const Clock::time_point start = Clock::now();
  const std::vector<std::filesystem::path> training_files = split_files(files, "training");
  const std::vector<LabelledPattern> training =
      load_labelled_patterns(training_files, labeller, true);
  const std::vector<LabelledPattern> held_out =
      load_labelled_patterns(split_files(files, "held-out"), labeller);
  const double feature_seconds = seconds_since(start);
  std::printf(
      "%zu patterns: %zu training (+%zu variants: whole chests, tops, taller and shorter cuts, "
      "tops lengthened at the hem), "
      "%zu held out (position %% 5 == 0); meshing and features in %.1f s\n",
      files.size(), training_files.size(), training.size() - training_files.size(), held_out.size(),
      feature_seconds);

  const Clock::time_point training_start = Clock::now();
  const TrainingRun run = train_classifier(training, options);
  const double training_seconds = seconds_since(training_start);
  const auto mean_loss = [&](std::size_t epoch) {
    double total = 0.0;
    for (const auto& losses : run.epoch_losses)
      total += losses[epoch] / run.epoch_losses.size();
    return total;
  };
  const std::size_t epochs = run.epoch_losses.front().size();
  for (std::size_t epoch = 0; epoch < epochs; ++epoch)
    if (epoch % 20 == 0 || epoch + 1 == epochs)
      std::printf("epoch %4zu  loss %.4f (mean over the ensemble)\n", epoch + 1, mean_loss(epoch));
  std::printf("trained %d networks of %d parameters in %.1f s (%d epochs)\n", options.ensemble,
              run.members.front().parameter_count(), training_seconds, options.epochs);

  const GatShape& shape = options.shape;
  save_classifier_weights(
      *output, run.members,
      {{"command", "garment-init train-classifier " +
                       std::filesystem::path(folder).lexically_normal().filename().string() +
                       " --epochs " + std::to_string(options.epochs) + " --ensemble " +
                       std::to_string(options.ensemble) + " --seed " +
                       std::to_string(options.seed)},
       {"data", std::filesystem::path(folder).lexically_normal().filename().string() + " (" +
                    std::to_string(files.size()) + " patterns)"},
       {"split", "training = name-sorted position % 5 != 0 (" +
                     std::to_string(training_files.size()) + " patterns, " +
                     std::to_string(training.size() - training_files.size()) +
                     " variants: whole chests, tops alone, chests alone, each also 1.4 and 0.75 "
                     "times as tall)"},
       {"labels", "panel_regions.json class7, skirt panels by placement (side gores: other)"},
       {"network", std::to_string(shape.heads) + " heads x " + std::to_string(shape.head_width) +
                       ", then " + std::to_string(shape.classes) + " classes"},
       {"optimiser", "AdamW lr " + std::to_string(options.learning_rate) + " cosine to 1/10, " +
                         "weight decay " + std::to_string(options.weight_decay) + ", batch " +
                         std::to_string(options.batch_patterns) + " patterns"},
       {"epochs", std::to_string(options.epochs)},
       {"ensemble", std::to_string(options.ensemble) + " networks, seeds seed .. seed + " +
                        std::to_string(options.ensemble - 1) + ", probabilities averaged"},
       {"seed", std::to_string(options.seed)},
       {"final_loss", std::to_string(mean_loss(epochs - 1))}});
  std::printf("wrote %s\n\nheld-out evaluation\n", output->c_str());
  const ClassificationReport report = evaluate_classifier(PieceClassifier(run.members), held_out);
  std::cout << format_classification_report(report);
  return kSuccess;
}

int classify_eval_command(const std::vector<std::string>& args) {
  const CommandLine line(args, {"--json"}, {"--weights", "--regions", "--split"});
  const std::string folder = line.only_positional("data folder");
  const std::string split = line.value("--split").value_or("held-out");
  const std::vector<std::filesystem::path> files = split_files(dataset_files(folder), split);
  const PanelLabeller labeller = PanelLabeller::load(regions_path(line, folder));
  const PieceClassifier classifier = PieceClassifier::load(
      line.value("--weights").value_or(default_classifier_weights_path().string()));
  const ClassificationReport report =
      evaluate_classifier(classifier, load_labelled_patterns(files, labeller));
  if (line.has("--json"))
    std::cout << classification_report_json(report) << "\n";
  else
    std::cout << folder << " (" << split << ")\n" << format_classification_report(report);
  return kSuccess;
}

}  // namespace garment::cli
