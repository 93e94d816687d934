// SPDX-License-Identifier: MIT
// Fuzz target: what `report --from` reads back, on arbitrary bytes: the input up to its first
// NUL byte as a check's figures (<stem>_check.json, which names its pictures), the rest as
// converge's CSV beside it, then the page built from what was read. Every picture the figures
// name is embedded only from inside their folder.
#include <cstdint>
#include <string>

#include "tests/fuzz/fuzz_support.h"
#include "tools/check.h"
#include "tools/report_html.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::string bytes(reinterpret_cast<const char *>(data), size);
    size_t nul = bytes.find('\0');
    std::string json = bytes.substr(0, nul);
    std::string csv = nul == std::string::npos ? std::string() : bytes.substr(nul + 1);
    std::string jsonPath = rt::fuzz::writeInput(reinterpret_cast<const uint8_t *>(json.data()),
                                                json.size(), "in_check.json");
    rt::fuzz::writeInput(reinterpret_cast<const uint8_t *>(csv.data()), csv.size(),
                         "in_converge.csv");
    // std::runtime_error naming the file is these readers' documented outcome of bad input
    rt::fuzz::expectCleanFailure(
        [&] {
            rt::cli::ReportScene scene;
            scene.scene = "in.scad";
            scene.povray = rt::cli::readCheckResult(jsonPath);
            const rt::cli::CheckResult &r = *scene.povray;
            const std::string *names[3] = {&r.refereePicture, &r.scadrayPicture, &r.diffPicture};
            for (int i = 0; i < 3; ++i) {
                if (names[i]->empty()) continue;
                try {
                    scene.povrayPictures[i] = rt::cli::dataUri(r.dir, *names[i]);
                } catch (const std::runtime_error &) {
                }
            }
            try {
                scene.converge = rt::cli::readConvergeFiles(r.dir, "in");
            } catch (const std::runtime_error &) {
            }
            rt::cli::ReportPage page;
            page.scenes.push_back(std::move(scene));
            rt::cli::reportHtml(page);
        },
        true);
    return 0;
}
