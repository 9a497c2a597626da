// sizing.reducer.* (the gear application factor after ISO 6336-6) and sizing.motor.* (the motor's
// starts after IEC 60034-1), SizingInputs.h; analysis/GearDuty.h and analysis/MotorDuty.h use them.
#include "scene/SceneReader.h"

namespace rollerdyn::scene_detail {

void readGearAndDutyRatings(const Reader& in, SizingInputs& z) {
  ReducerRatings& r = z.reducer;
  r.application_factor = in.number("sizing.reducer.application_factor");
  r.rated_torque = in.number("sizing.reducer.rated_torque");
  r.max_torque = in.number("sizing.reducer.max_torque");
  r.sn_exponent = in.number("sizing.reducer.sn_exponent");
  MotorDutyRatings& m = z.motor;
  m.locked_rotor_time = in.number("sizing.motor.locked_rotor_time");
  m.no_load_starts = in.number("sizing.motor.no_load_starts");
}

}  // namespace rollerdyn::scene_detail
