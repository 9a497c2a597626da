// Scene and SceneError for Python: the scene file's parser, errors with the same file, line, key
// and did-you-mean text as the command line.
#include <pybind11/stl.h>

#include <yaml-cpp/yaml.h>

#include "python/Bindings.h"
#include "python/PyConvert.h"
#include "python/PyScene.h"
#include "report/HtmlReport.h"
#include "report/SceneTable.h"
#include "scene/SceneError.h"
#include "scene/SceneSchema.h"

namespace rollerdyn::python {

namespace {

// A value text of the parameter table as the Python value it stands for, by the key's kind.
py::object typedValue(const KeySpec& spec, const std::string& text) {
  switch (spec.kind) {
    case KeyKind::Number:
    case KeyKind::NumberList: {
      const YAML::Node n = YAML::Load(text);
      if (!n.IsSequence()) return py::float_(n.as<double>());
      py::list l;  // a per-cart key given as a list: one float per cart
      for (const auto& e : n) l.append(py::float_(e.as<double>()));
      return std::move(l);
    }
    case KeyKind::Integer: return py::int_(YAML::Load(text).as<long long>());
    case KeyKind::Flag: return py::bool_(text == "true" || text == "True" || text == "TRUE");
    case KeyKind::Sides: {
      const YAML::Node n = YAML::Load(text);
      if (!n.IsSequence()) return py::str(n.Scalar());
      py::list l;
      for (const auto& e : n) l.append(e.Scalar());
      return std::move(l);
    }
    default: return py::str(text);
  }
}

std::vector<SceneParameterRow> rowsOf(const PyScene& s) { return sceneParameterRows(s.input(), s.overrides()); }

py::list rowList(const std::vector<SceneParameterRow>& rows) {
  py::list l;
  for (const SceneParameterRow& r : rows) l.append(py::make_tuple(r.key, r.value, r.unit, r.origin, r.meaning));
  return l;
}

// Scene.from_data: a dict of scene keys, as the YAML text it stands for.
PyScene sceneFromData(py::handle data, const std::string& name) {
  if (!py::isinstance<py::dict>(data))
    throw py::type_error("Scene.from_dict: expected a dict of scene keys, got " +
                         py::str(py::type::handle_of(data).attr("__name__")).cast<std::string>());
  return PyScene::fromData(yamlValueText(data), name);
}

// Scene.with_: the scene with more overrides, {dotted key path: value}.
PyScene sceneWith(const PyScene& s, const py::dict& changes) {
  std::vector<std::string> more;
  for (auto item : changes) {
    if (!py::isinstance<py::str>(item.first))
      throw py::type_error("Scene.with_: keys are dotted key paths (text), e.g. 'crank.offset_deg'");
    more.push_back(item.first.cast<std::string>() + "=" + yamlValueText(item.second));
  }
  return s.with(more);
}

// Scene.value: one key's value, typed; a key the schema does not know is a KeyError with the hint.
py::object sceneValue(const PyScene& s, const std::string& key) {
  const KeySpec* spec = findSceneKey(key);
  if (!spec) {
    try {
      requireSceneKey("scene[" + key + "]", key);
    } catch (const std::invalid_argument& e) {
      throw py::key_error(e.what());
    }
  }
  if (key == "source") return py::str(s.scene().source);
  for (const SceneParameterRow& r : rowsOf(s))
    if (r.key == key) return typedValue(*spec, r.value);
  return py::none();  // a conditional key the scene leaves to the parser
}

// (key, value) of every key the file or an override gives, typed, in schema order.
py::list givenValues(const PyScene& s) {
  py::list l;
  l.append(py::make_tuple("source", s.scene().source));
  for (const SceneParameterRow& r : rowsOf(s))
    if (r.origin != "default") l.append(py::make_tuple(r.key, typedValue(*findSceneKey(r.key), r.value)));
  return l;
}

// SceneError: a ValueError with the file, line, key, expected, got and origin of the message.
void bindSceneError(py::module_& m) {
  static py::exception<SceneError> scene_error(m, "SceneError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SceneError& e) {
      py::object err = py::reinterpret_borrow<py::object>(scene_error.ptr())(e.what());
      err.attr("file") = e.file();
      err.attr("line") = e.line() > 0 ? py::object(py::int_(e.line())) : py::object(py::none());
      err.attr("key") = e.key();
      err.attr("expected") = e.expected();
      err.attr("got") = e.got();
      err.attr("origin") = e.origin();
      PyErr_SetObject(scene_error.ptr(), err.ptr());
    }
  });
}

void bindSceneClass(py::module_& m) {
  py::class_<PyScene>(m, "Scene")
      .def_static("load", &PyScene::load, py::arg("path"))
      .def_static("from_data", &sceneFromData, py::arg("data"), py::arg("name"))
      .def("with_", &sceneWith, py::arg("changes"))
      .def_property_readonly("name", [](const PyScene& s) { return s.scene().name; })
      .def_property_readonly("path", [](const PyScene& s) { return s.file().empty() ? py::object(py::none()) : py::object(py::str(s.file())); })
      .def_property_readonly("overrides", [](const PyScene& s) { return s.overrides(); })
      .def_property_readonly("source", [](const PyScene& s) { return s.scene().source; })
      .def_property_readonly("effects", [](const PyScene& s) { return s.scene().effects(); })
      .def_property_readonly("text", [](const PyScene& s) { return s.input().text; })
      .def("parameters", [](const PyScene& s) { return rowList(rowsOf(s)); })
      .def("derived", [](const PyScene& s) { return rowList(derivedParameterRows(s.scene())); })
      .def("value", &sceneValue, py::arg("key"))
      .def("given", &givenValues)
      .def("html", [](const PyScene& s) { return sceneParametersHtml(rowsOf(s), derivedParameterRows(s.scene())); });
}

}  // namespace

void bindScene(py::module_& m) {
  bindSceneError(m);
  bindSceneClass(m);
}

}  // namespace rollerdyn::python
