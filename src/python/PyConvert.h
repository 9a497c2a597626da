// Conversions between the library's data and Python objects, for the bindings (Module.cpp):
// JSON (summary.json and friends) to dicts, tables to NumPy arrays, and Python values to the
// YAML text of a scene value, so that a dict or an override from Python passes exactly the
// parser a scene file passes.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "io/Table.h"
#include "studies/Sweep.h"

namespace rollerdyn::python {

namespace py = pybind11;

// null -> None, numbers -> int or float, strings, lists, objects -> dict (keys in JSON order).
py::object toPython(const nlohmann::json& j);

// A Python value as YAML flow text: bool -> true/false, None -> null, int -> digits, float ->
// repr (round-trips; .nan, .inf), str -> plain when YAML reads it back as the same text, else
// double-quoted (so "60" stays text, as a quoted "60" in a file does), list/tuple -> [..],
// dict -> {k: v, ..}; NumPy scalars as their Python counterparts. Throws TypeError otherwise.
std::string yamlValueText(py::handle value);

// {"columns": [names], "units": [units of io/Table.h], "values": 2-D float64 array rows x columns}.
py::dict tableToPython(const Table& table);

// A study's table (Sweep.h StudyColumn) as {"columns", "units", "data": {name: list or array}}.
py::dict studyTableToPython(const std::vector<StudyColumn>& table);

}  // namespace rollerdyn::python
