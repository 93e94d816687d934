// SPDX-License-Identifier: MIT
// `scadray report`: `check` (and `converge`, and the OpenSCAD referee, when asked) over many
// scenes, or over the figures earlier checks left (`--from`), written as one self-contained
// HTML page. A scene that fails or cannot be checked is a row of the page, never the end of it.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "core/render/renderer.h"
#include "core/system/input_file.h"
#include "core/system/subprocess.h"
#include "exporters/povray/pov_runner.h"
#include "exporters/povray/pov_writer.h"
#include "tools/check.h"
#include "tools/cli_common.h"
#include "tools/commands.h"
#include "tools/openscad_runner.h"
#include "tools/report_html.h"

namespace rt::cli {

namespace {

namespace fs = std::filesystem;

/// Highest samples per pixel of the converge levels unless told otherwise: 1 to 16 spp, and a
/// reference of 128, keep a report over a whole suite within minutes.
constexpr int kDefaultConvergeSamples = 16;

struct ReportArgs {
    CheckArgs check;  ///< the scene options and the check options; scene.input unused
    std::vector<std::string> inputs, from;
    std::string output = "report.html", filesDir, title = "scadray report";
    bool converge = false, openscad = false, linkImages = false, quiet = false;
    int convergeSamples = kDefaultConvergeSamples;
};

std::string lower(std::string s) {
    for (auto &c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool isSceneFile(const fs::path &p) {
    static const std::set<std::string> kExtensions = {".scad", ".gltf", ".glb", ".stl", ".off"};
    // scadray.scad is the library of the metadata modules, not a scene
    return kExtensions.count(lower(p.extension().string())) && p.filename() != "scadray.scad";
}

/// The scenes the arguments name: a folder's scene files (not its subfolders), a list
/// file's lines (.txt or .list; blank lines and # comments skipped; relative to the list's
/// folder), or a scene file itself (one that does not exist becomes a row with that error).
std::vector<std::string> gatherScenes(const std::vector<std::string> &inputs) {
    std::vector<std::string> scenes;
    for (const std::string &in : inputs) {
        fs::path p(in);
        std::error_code ec;
        if (fs::is_directory(p, ec)) {
            std::vector<std::string> found;
            for (const auto &e : fs::directory_iterator(p))
                if (e.is_regular_file() && isSceneFile(e.path()))
                    found.push_back(e.path().string());
            if (found.empty())
                std::cerr << "scadray: warning: " << in << ": no scene files in this folder\n";
            std::sort(found.begin(), found.end());
            scenes.insert(scenes.end(), found.begin(), found.end());
        } else if (std::string ext = lower(p.extension().string());
                   ext == ".txt" || ext == ".list") {
            std::istringstream list(readInputFile(in, kMaxReportFileBytes));
            std::string line;
            while (std::getline(list, line)) {
                size_t a = line.find_first_not_of(" \t\r"), b = line.find_last_not_of(" \t\r");
                if (a == std::string::npos || line[a] == '#') continue;
                fs::path scene(line.substr(a, b - a + 1));
                scenes.push_back(scene.is_absolute() ? scene.string()
                                                     : (p.parent_path() / scene).string());
            }
        } else {
            scenes.push_back(in);
        }
    }
    return scenes;
}

/// Every check figure file under the folders of --from (recursively), sorted.
std::vector<std::string> gatherCheckFiles(const std::vector<std::string> &folders) {
    std::vector<std::string> files;
    for (const std::string &folder : folders) {
        std::error_code ec;
        if (!fs::is_directory(folder, ec))
            throw std::invalid_argument("--from: '" + folder + "' is not a folder");
        for (const auto &e : fs::recursive_directory_iterator(folder)) {
            std::string name = e.path().filename().string();
            if (e.is_regular_file() && name.size() > 11 &&
                name.compare(name.size() - 11, 11, "_check.json") == 0)
                files.push_back(e.path().string());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// A folder name for a scene's files: its folder's name and its stem ("crosscheck_fresnel"),
/// made unique.
std::string uniqueName(const std::string &scene, std::set<std::string> &taken) {
    fs::path p(scene);
    std::string parent = p.parent_path().filename().string();
    std::string base = (parent.empty() ? "" : parent + "_") + p.stem().string();
    for (auto &c : base)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
    std::string name = base;
    for (int i = 2; !taken.insert(name).second; ++i) name = base + "-" + std::to_string(i);
    return name;
}

/// The row key of a scene: its absolute, normalized path, so the same file named two ways
/// (relative here, absolute in a CTest run's figures) is one row.
std::string sceneKey(const std::string &scene) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(scene), ec);
    return ec ? scene : p.string();
}

CheckResult failedCheck(const CheckArgs &a, const std::string &dir, const std::string &error) {
    CheckResult r;
    r.scene = a.scene.input;
    r.referee = a.openscad ? "openscad" : "povray";
    r.error = error;
    r.width = a.width;
    r.height = a.height;
    r.dir = dir;
    return r;
}

/// One check, its error caught; its figures are left beside its pictures, as `check` leaves
/// them, so `report --from` can rebuild the page.
CheckResult runCheckCaught(const CheckArgs &a) {
    CheckResult r;
    try {
        r = checkScene(a);
    } catch (const std::exception &e) {
        r = failedCheck(a, a.outDir, errorMessage(e));
    }
    try {
        fs::create_directories(a.outDir);
        pov::writeTextFile(checkJsonPath(a.outDir, a.scene.input, a.openscad), checkResultJson(r));
    } catch (const std::exception &e) {
        std::cerr << "scadray: warning: " << printable(errorMessage(e)) << "\n";
    }
    return r;
}

/// `scadray converge` on the scene, as its own process (this binary), at the check's size,
/// with POV-Ray where installed; reads back its CSV and SVG.
ConvergeCurve runConverge(const ReportArgs &ra, const std::string &scene, const std::string &dir) {
    const CheckArgs &a = ra.check;
    std::error_code ec;
    fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw std::runtime_error("converge: cannot find the scadray binary (/proc/self/exe)");
    std::vector<std::string> args = {self.string(),
                                     "converge",
                                     fileArgument(scene),
                                     "-o",
                                     fileArgument(dir),
                                     "-q",
                                     "-W",
                                     std::to_string(a.width),
                                     "-H",
                                     std::to_string(a.height),
                                     "--max-samples",
                                     std::to_string(ra.convergeSamples),
                                     "-t",
                                     std::to_string(a.threads),
                                     "--supersample",
                                     std::to_string(a.supersample),
                                     "--timeout",
                                     std::to_string(a.timeout)};
    if (pov::povrayAvailable()) args.push_back("--povray");
    std::vector<std::string> sceneOptions = a.scene.optionArguments();
    args.insert(args.end(), sceneOptions.begin(), sceneOptions.end());
    std::string stem = safeFileStem(scene);
    ProcessOptions po;
    po.logFile = (fs::path(dir) / (stem + "_converge.log")).string();
    // Its own renders plus POV-Ray's, each of which may take the check's time limit
    po.timeoutSeconds = 2 * a.timeout;
    ProcessResult pr = runProcess(args, po);
    if (pr.timedOut)
        throw std::runtime_error("converge: ran past " + std::to_string(po.timeoutSeconds) + " s");
    if (pr.exitCode != 0)
        throw std::runtime_error("converge failed (exit " + std::to_string(pr.exitCode) + "):\n" +
                                 lastLines(pr.log, 8));
    return readConvergeFiles(dir, stem);
}

/// What the page refers to for each picture of a check: the file's bytes as a data: URI, or
/// with --link-images a link relative to the page. A picture that cannot be read stays a
/// link, which the page then counts as broken.
PictureSources pictureSources(const CheckResult &r, const fs::path &pageDir, bool link) {
    PictureSources out;
    const std::string *names[3] = {&r.refereePicture, &r.scadrayPicture, &r.diffPicture};
    for (int i = 0; i < 3; ++i) {
        if (names[i]->empty()) continue;
        fs::path file = fs::path(r.dir) / *names[i];
        std::error_code ec;
        fs::path rel = fs::relative(fs::absolute(file), pageDir, ec);
        std::string linkSrc = urlPath((ec || rel.empty() ? fs::absolute(file) : rel).string());
        if (link) {
            out[i] = linkSrc;
            continue;
        }
        try {
            out[i] = dataUri(r.dir, *names[i]);
        } catch (const std::exception &e) {
            std::cerr << "scadray: warning: " << printable(e.what()) << "\n";
            out[i] = linkSrc;
        }
    }
    return out;
}

std::string verdictWord(const ReportScene &s) {
    static const char *words[] = {"ERROR", "DIFFERENT", "PASS"};
    return words[s.rank()];
}

int runReport(const ReportArgs &ra) {
    using clock = std::chrono::steady_clock;
    auto start = clock::now();
    requireOutputFile(ra.output, "-o");
    if (ra.inputs.empty() && ra.from.empty())
        throw std::invalid_argument("report: give scenes, folders or lists of scenes, or --from");
    std::vector<std::string> scenes = gatherScenes(ra.inputs);
    std::vector<std::string> checkFiles = gatherCheckFiles(ra.from);
    if (scenes.empty() && checkFiles.empty())
        throw std::invalid_argument("report: no scenes and no check figures (*_check.json) found");
    if (!scenes.empty() && !pov::povrayAvailable())
        throw std::invalid_argument(
            "POV-Ray (povray) is not installed; scripts/setup.sh installs it");
    if (!scenes.empty() && ra.openscad && !openscadAvailable())
        throw std::invalid_argument(
            "OpenSCAD (openscad) is not installed; scripts/setup.sh installs it");
    // Fail on a bad -D before any work
    (void)ra.check.scene.loadOptions(true);

    fs::path out(ra.output);
    fs::path pageDir = fs::absolute(out).parent_path();
    fs::path filesDir = ra.filesDir.empty() ? out.parent_path() / (out.stem().string() + "_files")
                                            : fs::path(ra.filesDir);

    std::vector<ReportScene> rows;
    std::map<std::string, size_t> rowOf;
    auto row = [&](const std::string &scene) -> ReportScene & {
        auto [it, fresh] = rowOf.emplace(sceneKey(scene), rows.size());
        if (fresh) {
            rows.emplace_back();
            rows.back().scene = scene;
        }
        return rows[it->second];
    };

    // Figures earlier checks left (a CTest run's build/tests/povray_check, say)
    for (const std::string &path : checkFiles) {
        try {
            CheckResult r = readCheckResult(path);
            ReportScene &s = row(r.scene.empty() ? path : r.scene);
            std::string stem = safeFileStem(r.scene);
            fs::path csv = fs::path(r.dir) / (stem + "_converge.csv");
            if (r.referee == "openscad") {
                s.openscad = std::move(r);
            } else {
                s.povray = std::move(r);
            }
            std::error_code ec;
            if (!s.converge && fs::exists(fs::symlink_status(csv, ec)))
                s.converge = readConvergeFiles(r.dir, stem);
        } catch (const std::exception &e) {
            row(path).error = errorMessage(e);
        }
    }

    // The scenes, one after the other, each check using every thread
    std::set<std::string> taken;
    for (size_t i = 0; i < scenes.size(); ++i) {
        const std::string &scene = scenes[i];
        ReportScene &s = row(scene);
        std::string dir = (filesDir / uniqueName(scene, taken)).string();
        CheckArgs a = ra.check;
        a.scene.input = scene;
        a.outDir = dir;
        a.quiet = true;
        a.openscad = false;
        s.povray = runCheckCaught(a);
        if (ra.openscad) {
            if (lower(fs::path(scene).extension().string()) == ".scad") {
                a.openscad = true;
                s.openscad = runCheckCaught(a);
            } else {
                s.openscadNote = "not run: OpenSCAD reads .scad scenes only";
            }
        }
        if (ra.converge && s.povray->error.empty()) {
            try {
                s.converge = runConverge(ra, scene, dir);
            } catch (const std::exception &e) {
                s.error = errorMessage(e);
            }
        }
        if (!ra.quiet) {
            std::string line = "[" + std::to_string(i + 1) + "/" + std::to_string(scenes.size()) +
                               "] " + scene + ": " + verdictWord(s);
            if (s.povray->error.empty()) {
                char buf[128];
                std::snprintf(buf, sizeof buf, " (POV-Ray %.2f s, scadray %.2f s)",
                              s.povray->refereeSeconds(), s.povray->scadraySeconds);
                line += buf;
            }
            std::cerr << line << "\n";
        }
    }

    // The page: failures first, each scene named relative to the current folder when it is
    // inside it (a CTest run's figures name scenes by absolute paths)
    ReportPage page;
    page.title = ra.title;
    for (ReportScene &s : rows) {
        std::error_code ec;
        fs::path rel = fs::relative(fs::absolute(s.scene), fs::current_path(), ec);
        if (!ec && !rel.empty() && *rel.begin() != "..") s.label = rel.string();
    }
    sortFailuresFirst(rows);
    for (ReportScene &s : rows) {
        if (s.povray) s.povrayPictures = pictureSources(*s.povray, pageDir, ra.linkImages);
        if (s.openscad) s.openscadPictures = pictureSources(*s.openscad, pageDir, ra.linkImages);
    }
    page.scenes = std::move(rows);
    if (!page.scenes.empty() && (ra.converge || !checkFiles.empty())) {
        std::string chart = findChartJs();
        bool anyCurve = std::any_of(page.scenes.begin(), page.scenes.end(),
                                    [](const ReportScene &s) { return s.converge.has_value(); });
        if (anyCurve && chart.empty()) {
            std::cerr << "scadray: warning: Chart.js (Debian package libjs-chart.js) not found; "
                         "the converge plots are converge's own SVG pictures, not interactive\n";
        } else if (anyCurve) {
            std::ifstream js(chart, std::ios::binary);
            page.chartJs.assign(std::istreambuf_iterator<char>(js), {});
        }
    }
    std::time_t now = std::time(nullptr);
    char when[64];
    std::strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    page.generated = std::string("generated ") + when + " by scadray " SCADRAY_VERSION;
    if (!scenes.empty()) {
        const CheckArgs &a = ra.check;
        page.settings = std::to_string(a.width) + "x" + std::to_string(a.height) + ", POV-Ray " +
                        std::to_string(a.supersample) + "x" + std::to_string(a.supersample) +
                        " supersampled, scadray " + std::to_string(a.batches) + " batches x " +
                        std::to_string(a.samples) + " spp";
        if (ra.converge)
            page.settings += ", converge 1 to " + std::to_string(ra.convergeSamples) + " spp";
    }
    if (!checkFiles.empty())
        page.settings += std::string(page.settings.empty() ? "" : "; ") + "figures of " +
                         std::to_string(checkFiles.size()) + " earlier checks";
    page.wallSeconds = std::chrono::duration<double>(clock::now() - start).count();
    std::string html = reportHtml(page);
    pov::writeTextFile(ra.output, html);

    int counts[3] = {0, 0, 0};
    for (const ReportScene &s : page.scenes) ++counts[s.rank()];
    std::printf("report: %zu scenes: %d passed, %d different, %d errors; %s (%.1f MB) in %.2f s\n",
                page.scenes.size(), counts[2], counts[1], counts[0], ra.output.c_str(),
                html.size() / 1e6, page.wallSeconds);
    return counts[0] + counts[1] == 0 ? kExitOk : kExitInputError;
}

}  // namespace

void addReportCommand(CLI::App &app, std::function<int()> &action) {
    auto args = std::make_shared<ReportArgs>();
    CLI::App *cmd = app.add_subcommand(
        "report",
        "Run check over many scenes (files, folders, lists) or read earlier checks' figures "
        "(--from), and write one self-contained HTML report, failures first (exit 0 all "
        "passed, 1 any different or failed, 2 bad usage)");
    // The scene options of every command, without its one positional scene: this command
    // takes many
    args->check.scene.addTo(*cmd, SceneArgs::Positional::None);
    cmd->add_option("scenes", args->inputs,
                    "Scene files, folders (their scene files) and lists of scenes (.txt or "
                    ".list, one path a line, relative to the list)");
    cmd->add_option("-o,--output", args->output, "The HTML file (default report.html)");
    cmd->add_option("--files", args->filesDir,
                    "Folder for the checks' files (default <output stem>_files beside it)");
    cmd->add_option("--from", args->from,
                    "Folder of earlier checks' figures (*_check.json, searched recursively), "
                    "e.g. build/tests/povray_check after `ctest -L povray`");
    cmd->add_option("--title", args->title, "Title of the page");
    cmd->add_flag("--converge", args->converge,
                  "Also run converge on each scene (error against time, with POV-Ray's time)");
    addNumber(*cmd, "--converge-samples", args->convergeSamples,
              "converge: highest samples per pixel (levels 1, 2, 4, ... up to it)", 1,
              kMaxSamplesPerPixel);
    cmd->add_flag("--openscad", args->openscad,
                  "Also run the OpenSCAD referee (check --openscad) on each .scad scene");
    cmd->add_flag("--link-images", args->linkImages,
                  "Link the pictures beside the page instead of embedding them (a smaller "
                  "page that needs its _files folder)");
    addCheckOptions(*cmd, args->check);
    cmd->add_flag("-q,--quiet", args->quiet, "No progress line per scene");
    cmd->callback([args, &action]() { action = [args]() { return runReport(*args); }; });
}

}  // namespace rt::cli
