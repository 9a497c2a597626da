// The sections of the scene schema's key table, each in reference order (SceneSchemaRun.cpp,
// SceneSchemaMechanism.cpp, SceneSchemaMotor.cpp, SceneSchemaDriveTrain.cpp, SceneSchemaLoads.cpp,
// SceneSchemaSizing.cpp, SceneSchemaSignOff.cpp); SceneSchema.cpp puts them together in the
// reference's order. Internal to the schema.
#pragma once

#include <string>
#include <vector>

#include "scene/SchemaBuilders.h"

namespace rollerdyn {
namespace schema_builders {

// The papers a key's source cites, by short name.
inline const std::string L2018 = "Loveikin, Pochka, Romasevych (2018)";
inline const std::string L2007 = "Loveikin and Pochka (2007)";
inline const std::string CAM = "Loveikin and Pochka (cam drive paper)";
inline const std::string EB = "the energy-balanced drive paper";

}  // namespace schema_builders

std::vector<KeySpec> runSchemaKeys();           // source, simulation.*
std::vector<KeySpec> initialStateSchemaKeys();  // initial.*
std::vector<KeySpec> crankSchemaKeys();         // crank.*
std::vector<KeySpec> crankshaftSchemaKeys();    // crankshaft.*
std::vector<KeySpec> rodSchemaKeys();           // rods.*
std::vector<KeySpec> driveSchemaKeys();         // drive.type, cam.*
std::vector<KeySpec> cartSchemaKeys();          // carts.*
std::vector<KeySpec> motorSchemaKeys();         // motor.* but circuit, catalogue, start, stop
std::vector<KeySpec> motorCircuitSchemaKeys();  // motor.circuit.*
std::vector<KeySpec> motorCatalogueSchemaKeys();  // motor.catalogue.*
std::vector<KeySpec> motorSwitchingSchemaKeys();  // motor.start.*, motor.stop.*
std::vector<KeySpec> reducerSchemaKeys();       // reducer.*
std::vector<KeySpec> couplingSchemaKeys();      // coupling.*
std::vector<KeySpec> flywheelSchemaKeys();      // flywheel.*
std::vector<KeySpec> loadSchemaKeys();          // loads.*
std::vector<KeySpec> sizingSchemaKeys();        // sizing.* but the sign-off (signOffSchemaKeys)
std::vector<KeySpec> reducedModelSchemaKeys();  // reduced.*

}  // namespace rollerdyn
