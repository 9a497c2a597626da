#include "studies/SignOff.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "io/AtomicFile.h"
#include "io/ReadFile.h"
#include "report/SignOffSheetHtml.h"
#include "report/ToolVersion.h"

namespace rollerdyn {

namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Prints `html` to `pdf` with `chromium`; "" when written, else why not.
std::string printPdf(const std::string& chromium, const fs::path& html, const fs::path& pdf) {
  char profile[] = "/tmp/rollerdyn-chromium-XXXXXX";
  if (!::mkdtemp(profile)) return "no temporary folder for Chromium's profile";
  const std::string cmd = "timeout 120 " + quoted(chromium) +
                          " --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking "
                          "--disable-component-update --disable-sync --no-pdf-header-footer --user-data-dir=" +
                          quoted(profile) + " --print-to-pdf=" + quoted(pdf.string()) + " " +
                          quoted("file://" + fs::absolute(html).string()) + " >/dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  std::error_code ec;
  fs::remove_all(profile, ec);
  if (fs::exists(pdf) && fs::file_size(pdf) > 0) return "";
  return "Chromium (" + chromium + ") did not print it (exit status " + std::to_string(rc) + ")";
}

}  // namespace

SignOffSheet signOffSheetOf(const nlohmann::json& summary, const std::string& scene_name, const std::string& scene_file,
                            const std::vector<std::string>& overrides) {
  SignOffSource src;
  src.scene_name = scene_name;
  if (!scene_file.empty()) {
    src.scene_path = fs::absolute(scene_file).lexically_normal().string();
    src.scene_text = readFileContents(scene_file, "scene file");
  } else {
    src.scene_path = "(not a file: a scene built in Python)";
  }
  src.overrides = overrides;
  src.tool_version = toolVersionText();
  src.date = utcTimestamp();
  return buildSignOffSheet(summary, src);
}

std::string findChromium() {
  if (const char* own = std::getenv("ROLLERDYN_CHROMIUM")) return own;
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "/usr/bin:/bin";
  for (std::size_t start = 0; start <= dirs.size();) {
    const std::size_t colon = dirs.find(':', start);
    const std::string dir = dirs.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    for (const char* name : {"chromium", "chromium-browser"}) {
      const fs::path p = fs::path(dir) / name;
      if (!dir.empty() && ::access(p.c_str(), X_OK) == 0) return p.string();
    }
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  return "";
}

SignOffFiles writeSignOffFiles(const SignOffSheet& sheet, const std::string& out_dir) {
  SignOffFiles f;
  const fs::path dir(out_dir);
  f.json = (dir / "signoff.json").string();
  f.html = (dir / "signoff.html").string();
  const fs::path pdf = dir / "signoff.pdf";
  std::error_code ec;
  fs::remove(pdf, ec);  // never a PDF of an earlier sheet beside this one
  writeFileAtomic(f.json, signOffJson(sheet).dump(2) + "\n");
  writeFileAtomic(f.html, signOffSheetHtml(sheet));
  const std::string chromium = findChromium();
  if (chromium.empty() || ::access(chromium.c_str(), X_OK) != 0) {
    f.pdf_not_written = "the PDF needs Chromium, which is not installed (Debian package chromium: apt-get install "
                        "chromium, or bash scripts/setup.sh); print signoff.html from a browser instead";
    return f;
  }
  f.pdf_not_written = printPdf(chromium, f.html, pdf);
  if (f.pdf_not_written.empty()) f.pdf = pdf.string();
  return f;
}

}  // namespace rollerdyn
