// CVODE's normal mode (advance to an output time, interpolate there) taken one internal step at a
// time, so that the end of every step can be observed: what happens between output times (the
// crank speed's extrema, analysis/CrankSpeedExtrema.h) is seen on the integrator's own steps.
//
// Same steps, same outputs as CV_NORMAL: the steps do not depend on the output times, and an
// output time inside the last step is interpolated with CVodeGetDky exactly as CV_NORMAL does.
// What CV_ONE_STEP does differently, and is undone here: it returns a root or the stop time
// where its step ends even when an output time lies before it, where CV_NORMAL returns the output
// time first and the root or the stop time on the next call. Such a return is kept pending and
// handed out on the call whose output time reaches it.
//
// Used by the CVODE driver (CvodeIntegrator.h) when its problem observes the steps.
#pragma once

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>

namespace rollerdyn {

class CvodeStepByStep {
 public:
  CvodeStepByStep() = default;
  CvodeStepByStep(const CvodeStepByStep&) = delete;
  CvodeStepByStep& operator=(const CvodeStepByStep&) = delete;
  ~CvodeStepByStep() { release(); }
  // Frees the copy of a pending return's y (before its SUNDIALS context goes).
  void release() {
    if (pending_y_) N_VDestroy(pending_y_);
    pending_y_ = nullptr;
    pending_ = false;
  }

  // After CVodeInit or CVodeReInit: no step taken since, nothing pending.
  void restarted() {
    stepped_ = false;
    pending_ = false;
  }

  // Advances `cv` towards t_out as CVode(cv, t_out, y, &t_ret, CV_NORMAL) would and returns its
  // flag; observe(t_step) is called after every internal step with y holding y(t_step) (for a
  // root, the root's time), while CVodeGetDky still reaches inside that step.
  template <class Observe>
  int advance(void* cv, double t_out, N_Vector y, realtype& t_ret, Observe&& observe) {
    if (pending_) return handOutPending(cv, t_out, y, t_ret);
    while (true) {
      realtype tn = t_out;
      CVodeGetCurrentTime(cv, &tn);
      if (stepped_ && tn >= t_out) return interpolate(cv, t_out, y, t_ret);  // the last step passed t_out
      const int flag = CVode(cv, t_out, y, &t_ret, CV_ONE_STEP);
      if (flag < 0) return flag;
      stepped_ = true;
      observe(double(t_ret));
      if (flag == CV_ROOT_RETURN || flag == CV_TSTOP_RETURN)
        return t_ret <= t_out ? flag : keepPending(cv, t_out, y, t_ret, flag);
      if (t_ret >= t_out) return t_ret > t_out ? interpolate(cv, t_out, y, t_ret) : flag;
    }
  }

 private:
  // The pending root or stop once t_out reaches it; before it, y interpolated at t_out in the
  // same step.
  int handOutPending(void* cv, double t_out, N_Vector y, realtype& t_ret) {
    if (t_out >= pending_t_) {
      N_VScale(1.0, pending_y_, y);
      t_ret = pending_t_;
      pending_ = false;
      return pending_flag_;
    }
    return interpolate(cv, t_out, y, t_ret);
  }

  // A root or stop (flag) at t_ret past t_out: kept for a later call, y interpolated at t_out.
  int keepPending(void* cv, double t_out, N_Vector y, realtype& t_ret, int flag) {
    if (!pending_y_) pending_y_ = N_VClone(y);
    N_VScale(1.0, y, pending_y_);
    pending_t_ = t_ret;
    pending_flag_ = flag;
    pending_ = true;
    return interpolate(cv, t_out, y, t_ret);
  }

  static int interpolate(void* cv, double t_out, N_Vector y, realtype& t_ret) {
    t_ret = t_out;
    return CVodeGetDky(cv, t_out, 0, y) == CV_SUCCESS ? CV_SUCCESS : CV_BAD_T;
  }

  bool stepped_ = false;
  bool pending_ = false;
  int pending_flag_ = CV_SUCCESS;
  double pending_t_ = 0.0;
  N_Vector pending_y_ = nullptr;
};

}  // namespace rollerdyn
