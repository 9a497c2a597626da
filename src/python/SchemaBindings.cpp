// The scene keys for Python (the same rows as docs/scene-reference.md) and the unit of a column.
#include <pybind11/stl.h>

#include "io/Table.h"
#include "python/Bindings.h"
#include "scene/SceneReference.h"

namespace rollerdyn::python {

namespace py = pybind11;

void bindSchema(py::module_& m) {
  m.def("scene_keys", [] {
    py::list rows;
    for (const SceneKeyDoc& k : sceneKeyDocs()) {
      py::dict d;
      d["key"] = k.key;
      d["section"] = k.section;
      d["unit"] = k.unit;
      d["presence"] = k.presence;
      d["default"] = k.default_value;
      d["condition"] = k.condition;
      d["allowed"] = k.allowed;
      d["meaning"] = k.meaning;
      d["source"] = k.source;
      rows.append(d);
    }
    return rows;
  });
  m.def("scene_reference_markdown", &sceneReferenceMarkdown);
  m.def("column_unit", &columnUnit, py::arg("name"));
}

}  // namespace rollerdyn::python
