#include "compare/ValidationItems.h"

#include <exception>

#include "scene/SceneParser.h"

namespace rollerdyn::validation {

Scene ItemContext::load(const std::string& file, const std::vector<std::string>& sets) const {
  return parseSceneFile(path(file), sets);
}

std::string ItemContext::command(const std::string& verb, const std::string& file,
                                 const std::vector<std::string>& sets) const {
  std::string c = "rollerdyn " + verb + " model/" + file;
  for (const auto& s : sets) c += " --set " + s;
  return c;
}

void ItemContext::log(const std::string& line) const {
  if (log_line) log_line(line);
}

bool ItemContext::interrupted() const { return interrupt && interrupt->load(); }

std::vector<ValidationSection> runValidationItems(const ItemContext& ctx, const std::vector<NamedItem>& items) {
  std::vector<ValidationSection> out;
  for (const NamedItem& item : items) {
    if (ctx.interrupted()) break;
    ctx.log(item.name);
    try {
      out.push_back(item.run(ctx));
    } catch (const std::exception& e) {
      ValidationSection s("item" + std::to_string(out.size() + 1), item.name);
      s.claim(false, std::string("the item ran to its end (it stopped: ") + e.what() + ")");
      out.push_back(std::move(s));
    }
  }
  return out;
}

}  // namespace rollerdyn::validation
