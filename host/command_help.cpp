// What each command's --help says besides its options (docs/cli.md is made from the same text):
// what the command does, what it writes, and what a user needs to know to run it.
#include <map>
#include <string>

#include "options.h"

namespace pedtrack::cli {

const char* commandAbout(const std::string& key) {
  static const std::map<std::string, const char*> about = {
      {"run",
       "Validates the whole pipeline and creates every plugin before the first frame (--out\n"
       "is created only then), then runs it frame by frame. --input replaces the pipeline's\n"
       "source: .bag -> rosbag, .ini (a scenario) -> sim, anything else -> rawlog; the\n"
       "source's other keys are dropped (give them again with --set source.KEY=VALUE).\n"
       "--set is applied after --input; a path given with --set is relative to the working\n"
       "directory, paths in the file to the file's folder.\n"
       "Outputs (--out DIR): tracks.csv and run.json always; detections.csv, clusters.csv\n"
       "and point_labels.bin when a stage produces them (docs/outputs.md).\n"
       "A live source (a device) is read on its own thread into --live-queue frames; when\n"
       "the stages fall behind, the oldest waiting frame is dropped and counted\n"
       "(frames_dropped). Files are read as the stages ask, never dropped.\n"
       "A stage that throws on a frame costs that frame only (frames_failed, warned).\n"
       "SIGINT/SIGTERM stop after the current frame; every output is still written.\n"
       "Exit codes: 0 success; 1 failure while running (corrupt data, device error; what\n"
       "was written is kept); 2 bad input (one line naming file, section and key; nothing\n"
       "written).\n"
       "Example: pedtrack run configs/people_2d_legs.ini --input walk.bag --out out/walk\n"},
      {"ros",
       "Runs a pipeline as a ROS1 node: its source is replaced by ros_topic (keeping the\n"
       "keys they share: topic, fixed_frame, base_frame, mounts, merge_window, so a bag\n"
       "pipeline works unchanged) and a ros_publish stage is appended as section [publish]\n"
       "unless the pipeline has one. Robot and sensor poses come from /tf (fixed_frame ->\n"
       "base_frame -> the message's frame). Publishes ~tracks (PoseArray), ~people\n"
       "(PointCloud2: x y z id vx vy yaw alpha beta cov_xx cov_xy cov_yy score status) and\n"
       "~markers (rviz), stamped with each scan's time. Runs until SIGINT/SIGTERM, or until\n"
       "the topics are quiet for source.idle_timeout s with source.end_on_idle = true.\n"
       "Needs a ROS master ($ROS_MASTER_URI): without one it exits 2 after\n"
       "source.master_timeout s. Outputs and exit codes as `pedtrack run`.\n"
       "Example: pedtrack ros configs/people_2d_legs.ini --topic /scan\n"},
      {"plugins",
       "Without NAME: every plugin found (--plugin-path dirs, then $PEDTRACK_PLUGIN_PATH,\n"
       "then lib/pedtrack/plugins next to this program, then the install prefix; the first\n"
       "of a name wins) with its category and doc; a plugin built for another API version is\n"
       "listed with the reason it is refused. With NAME: every parameter with type, unit,\n"
       "default, range and doc. docs/plugins.md holds the same for every plugin.\n"},
      {"sim",
       "Simulates a scenario (docs/scenarios.md) into DIR/sim.rawlog (per frame a\n"
       "CObservationOdometry, label ODOMETRY, and the scan: CObservation2DRangeScan, label\n"
       "LASER, or CObservationVelodyneScan, label VELODYNE, raw VLP-16 packets), so every\n"
       "pipeline runs on it unchanged; DIR/truth.csv (one row per person per frame, hidden\n"
       "ones too, x,y in the odometry frame, world_x,world_y the true position) and\n"
       "DIR/truth_points.bin (who each return hit). The same scenario and seed give the same\n"
       "bytes. --seed replaces the scenario's: sensor noise, dropout, odometry noise, crowd\n"
       "and clutter layout, random walks. The `sim` plugin runs the same simulation inside\n"
       "a pipeline.\n"},
      {"eval",
       "Scores a run against truth.\n"
       "Tracks (--truth truth.csv --tracks tracks.csv, both repeatable): CLEAR MOT (MOTA,\n"
       "MOTP, ID switches, fragmentations; a previous match is kept while within the\n"
       "threshold, the rest paired by minimum total distance), IDF1, HOTA, position, heading,\n"
       "axis and semi-axes errors, NEES / NIS consistency against the two-sided 95 % chi-square\n"
       "region. Frames are the union of truth and track times (within 0.1 ms one frame).\n"
       "--following ID scores that person alone (false positives ignored).\n"
       "Against a bag of labelled legs (--truth BAG --tracks T): legs covered by a track\n"
       "within --threshold (0.35 m), rows near no leg, tracks on no person (laser frame).\n"
       "Against leg_tracker benchmark bags (annotated people, leg_tracker/Person, decoded\n"
       "from the bag's own message definition; --truth BAG --tracks T, repeatable: pooled):\n"
       "the benchmark's clear_mot.py rules on the people annotated after each scan (laser\n"
       "frame, 0.75 m), the tracks on no annotated person per scan (over all scans, and up\n"
       "to the last annotated one); --following scores a following recording (false\n"
       "positives not counted), --angles MIN,MAX keeps the bearings the benchmark scores\n"
       "(its moving-robot files: -80,12).\n"
       "Detections (--detections detections.csv or clusters.csv): per-frame assignment\n"
       "within the threshold; precision, recall, F1, recall by range.\n"
       "Segmentation (--truth-points truth_points.bin --labels point_labels.bin): ground,\n"
       "person and object point shares, plane errors, people one cluster / split / merged /\n"
       "missed, for all and for isolated people.\n"
       "Classifier models: `pedtrack eval --model M --help`; a run's decisions:\n"
       "`pedtrack eval --decisions D --help`. Bad input exits 2 before anything is printed.\n"},
      {"eval --model",
       "Scores classifier models on labelled clusters (the inputs of `pedtrack train`: a\n"
       "dataset file, --samples, or --pipeline with --sim / --positive / --negative): the\n"
       "confusion matrix in P2 Table 1's layout, detection and false-positive rates, ROC AUC\n"
       "(ties count one half) and two operating points: the best detection at <= 5 % false\n"
       "positives and the fewest false positives at >= 90 % detection. --k, --metric,\n"
       "--minkowski-p and --weighting replace a k-NN model's trained options for this\n"
       "evaluation only.\n"},
      {"eval --decisions",
       "A run's person decisions against simulated truth: reads RUN_DIR/point_labels.bin,\n"
       "detections.csv and tracks.csv (with their cluster column) and truth_points.bin. Each\n"
       "cluster a detection was made from is a sample whose truth is what most of its points\n"
       "hit. Reported for appearance alone and with motion (2x2 matrices, detection and\n"
       "false-positive rates, precision, accuracy), per cluster and frame and per object.\n"
       "Run the classifier with q_person = 0 so every cluster gets a detection. A missing\n"
       "file, or a CSV without the cluster column, exits 2.\n"},
      {"eval --kitti",
       "A run of the kitti source over KITTI object benchmark scans (DIR/velodyne) against\n"
       "their labels (DIR/label_2, camera frame, turned into the Velodyne's by DIR/calib):\n"
       "each labelled Pedestrian or Person_sitting found (a cluster called a person inside its\n"
       "box grown by --margin) or missed, and every cluster called a person inside the\n"
       "camera's field of view (the only part KITTI labels) named by the labelled object it\n"
       "lies on, or none. A row of time t belongs to scan t x --scan-rate (the source's\n"
       "default times). A missing label, calibration or detections file exits 2.\n"},
      {"montecarlo",
       "Runs PIPELINE on --runs simulations of SCENARIO, seed --seed-base + i for run i\n"
       "(DIR/run_NNN: `pedtrack run PIPELINE --input SCENARIO --set SRC.seed=...`), --jobs at\n"
       "a time (the runs' files do not depend on --jobs), and scores them together as\n"
       "`pedtrack eval` would (fixed frame, runs aligned by frame index): per truth id the\n"
       "frames matched, NEES / NIS inside fractions, position and heading RMSE per frame,\n"
       "ID switches per run and the runs whose identity survived. Writes\n"
       "DIR/montecarlo.json, consistency.csv and plots (nees_<id>.png, nis_<id>.png,\n"
       "rmse_<id>.png, heading_<id>.png, llr.png). A failed run is named with its seed and\n"
       "the others are scored (exit 1); bad arguments exit 2 before any run.\n"
       "Example: pedtrack montecarlo configs/people_2d_torso.ini\n"
       "  configs/scenarios/p4_circle.ini --runs 50 --out out/mc_circle\n"},
      {"montecarlo --compare",
       "Compares Monte Carlo result directories side by side (no simulation): DIR/compare.md\n"
       "(label, position RMSE, heading RMSE, axis RMSE, MOTA, ID switches, runs; also\n"
       "printed) and errors_<truth id>.png (distance and heading error against time, a\n"
       "colour per label). A missing directory or one without montecarlo.json exits 2.\n"},
      {"train",
       "Builds a person classifier model (k-NN: P2; SVM: P4) from labelled clusters: a\n"
       "dataset file (configs/training/*.ini), a samples CSV, or a pipeline with --sim /\n"
       "--positive / --negative inputs. Only the pipeline's source and segmenter stages run,\n"
       "so a detection pipeline trains the model it will use. With --positive, clusters at\n"
       "the label positions (or inside --region) are persons and the others left out.\n"
       "scripts/train-models.sh rebuilds every shipped model (the leg models need\n"
       "PEDTRACK_DATA, the folder holding leg_tracker/).\n"},
      {"render",
       "Draws a run over its rawlog (a .bag through the rosbag source) in the fixed frame, x\n"
       "to the right: points (coloured by --labels), tracks (torso ellipse, id, velocity\n"
       "arrow, 95 % covariance, trail), the truth (green outlines, dashed trails),\n"
       "detections (yellow crosses) and the sensor's path. A CSV row belongs to the frame\n"
       "whose time is within 0.1 ms of its t, else to the frame its `frame` column names.\n"
       "--out X.png with --frame: that frame; without: the whole run overlaid. --out X.mp4:\n"
       "one video frame per rawlog frame (OpenCV, mp4v).\n"
       "Example: pedtrack render --rawlog out/crowd/sim.rawlog --run out/crowd/tracks\n"
       "  --truth out/crowd/truth.csv --frame 150 --out crowd.png\n"},
      {"bench",
       "Measures speed (use a Release build):\n"
       "  default      replay throughput of the rawlog reader with no stages, on --scans\n"
       "               synthetic scans or on --input;\n"
       "  --scenario   frames per second the simulator produces on one thread;\n"
       "  --pipeline   every stage on --frames frames read and decoded beforehand, --repeat\n"
       "               passes, one thread: p50 / p99 / mean / max ms per stage (--points N\n"
       "               resamples every cloud to N points);\n"
       "  --model      a classifier model on batches of a samples file's vectors;\n"
       "  --suite      the whole benchmark: every shipped pipeline's speed against its\n"
       "               target, cost against points and people, every tracker on every\n"
       "               scenario, the soak; writes --report (BENCHMARKS.md) and its plots,\n"
       "               keeping the report's part measured by hand (from its marker line on).\n"
       "               Each timing runs in a child process of its own, one core; --quick\n"
       "               checks the suite in about two minutes.\n"},
      {"import",
       "Converts a ROS1 bag (or a rawlog) into a gz-compressed observations-format rawlog\n"
       "that MRPT's tools (rawlog-edit, RawLogViewer) and the rawlog source read: scans as\n"
       "CObservation2DRangeScan, clouds as CObservationPointCloud; with robot poses (/tf or\n"
       "odometry) each frame is preceded by a CObservationOdometry.\n"},
      {"docs",
       "Writes the documents generated from the code: plugins.md (every plugin's parameter\n"
       "declarations), cli.md (every command's --help) and scenarios.md (every scenario key\n"
       "and the shipped scenarios). Tests fail when the copies in docs/ are stale: run\n"
       "`pedtrack docs` from the repository root after changing a declaration or a help.\n"},
  };
  const auto it = about.find(key);
  return it == about.end() ? "" : it->second;
}

}  // namespace pedtrack::cli
