// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Inertia.h
 * @brief Heavy particles: the reduced Maxey-Riley equation (Haller and
 * Sapsis 2008) as one step of a particle's slip velocity, the maths every
 * engine shares.
 *
 * A particle of velocity v at x in the flow u follows
 *
 *     dv/dt = (u(x, t) - v) / tau + beta Du/Dt + (1 - beta) g,   dx/dt = v,
 *
 * with beta = 3 / (1 + 2 rho_p / rho_f) (0 for heavy particles, 1 for
 * neutrally buoyant ones, 3 for bubbles) and Du/Dt = du/dt + (u . grad) u.
 * The engines keep the slip s = v - u(x, t) instead of v: the massless
 * tracer's step moves a particle by the flow (with the trace's integrator),
 * and the slip adds its own displacement. Along the particle's path
 * du(x, t)/dt = Du/Dt + (s . grad) u, so the slip follows
 *
 *     ds/dt = -s / tau + a,   a = (1 - beta) (g - Du/Dt) - (s . grad) u
 *                               = (1 - beta) (g - du/dt) - (q . grad) u,
 *
 * with q = (1 - beta) u + s (SlipStepper::direction): one derivative along q, taken
 * from the cell's corners (VectorField::sampleAlong), not the whole gradient
 * (the same maths; the float rounding is that of this form). That is what
 * one step solves exactly for a held constant over the step (an
 * exponential integrator): with E = exp(-h / tau), M = tau (1 - E) and
 * S = tau (h - M),
 *
 *     s(t + h) = E s + M a,   displacement = M s + S a.
 *
 * (The same as T + (s - T) E and h T + M (s - T) with the terminal slip
 * T = tau a, written without T: with tau far above the step T is huge and
 * s - T cancels every digit of float; so M and S are computed in double,
 * S by its series where h / tau is small.) It is stable for any tau > 0,
 * however far below the step (E -> 0: the slip is tau a, the drift h tau a)
 * or above it (E -> 1: M -> h and S -> h^2 / 2, free fall under a), and
 * exact for a constant a (settling in still fluid, drag relaxation in a
 * uniform flow). tau -> 0 gives the tracer; tau = 0 is the tracer itself
 * (carriesInertia() is false, nothing runs).
 *
 * The GPU engine runs the same maths in Shaders/bp_slip.glsl (a slip pass
 * before advection and a share pass after the test, or both inside the
 * compute path's fused step).
 */
#ifndef BoundParticles_Inertia_h
#define BoundParticles_Inertia_h

#include "EngineParameters.h"
#include "TrilinearAlong.h"

#include <cmath>

namespace bp
{

/// beta = 3 / (1 + 2 R) for a density ratio R = rho_p / rho_f > 0.
inline float addedMassFactor(float densityRatio)
{
  return 3.0f / (1.0f + 2.0f * densityRatio);
}

/// Whether a step moves particles by their slip: Maxey-Riley with tau > 0.
inline bool carriesInertia(const Parameters& p)
{
  return p.inertia == Inertia::MaxeyRiley && p.responseTime > 0.0f;
}

/// A step's constants, the same for every particle.
struct InertiaStep
{
  float h = 0.0f;        ///< the step
  float decay = 1.0f;    ///< E = exp(-h / tau): what the drag leaves of the slip
  float memory = 0.0f;   ///< M = tau (1 - E): the slip's and the drift's share of a, s
  float settle = 0.0f;   ///< S = tau (h - M): the displacement per unit of a
  float buoyancy = 0.0f; ///< 1 - beta
  float gravity[3] = { 0, 0, 0 };
};

/// The constants of a step of size h (in double, then float).
inline InertiaStep inertiaStepOf(const Parameters& p, double h)
{
  InertiaStep k;
  k.h = float(h);
  if (!carriesInertia(p))
  {
    return k;
  }
  const double tau = p.responseTime;
  const double x = h / tau;
  const double memory = -tau * std::expm1(-x); // tau (1 - E), exact however small x is
  k.decay = float(std::exp(-x));
  k.memory = float(memory);
  // tau (h - M) = h^2 (1/2 - x/6 + x^2/24 - ...): h - M cancels as x -> 0.
  k.settle = float(x < 1e-3 ? h * h * (0.5 - x / 6.0 + x * x / 24.0) : tau * (h - memory));
  k.buoyancy = 1.0f - addedMassFactor(p.densityRatio);
  for (int a = 0; a < 3; ++a)
  {
    k.gravity[a] = p.gravity[a];
  }
  return k;
}

/// slipStep's arithmetic for one component (T = float) or for the three
/// in SSE lanes (T = Lanes): the same operations, so the same bits.
template <class T>
inline void slipStepOf(const InertiaStep& k, T gravity, T dudt, T along, T& slip, T& move)
{
  const T a = T(k.buoyancy) * (gravity - dudt) - along;
  move = T(k.memory) * slip + T(k.settle) * a;
  slip = T(k.decay) * slip + T(k.memory) * a;
}

/**
 * One particle's slip over a step: `dudt` = du/dt and `along` = (q . grad) u
 * for q = (1 - beta) u + s (SlipStepper::direction), both at its position at
 * the step's start. Updates `slip` and writes the displacement the slip adds
 * to the tracer's in `move`.
 */
inline void slipStep(
  const InertiaStep& k, const float dudt[3], const float along[3], float slip[3], float move[3])
{
  for (int c = 0; c < 3; ++c)
  {
    slipStepOf(k, k.gravity[c], dudt[c], along[c], slip[c], move[c]);
  }
}

/**
 * A particle's slip step as VectorField::sampleAlong runs it, between its
 * sampling of u and its derivative: direction() is q = (1 - beta) u + s
 * (the slip's acceleration needs (1 - beta) (u . grad) u + (s . grad) u,
 * which is (q . grad) u: one derivative instead of two), step() is
 * slipStep. In SSE lanes where the field samples in lanes, else component
 * by component: the same operations, the same bits.
 */
class SlipStepper
{
public:
  SlipStepper(const InertiaStep& k, float slip[3], float move[3])
    : K(k)
    , Slip(slip)
    , Move(move)
#if BOUNDPARTICLES_SSE2
    , Held(Lanes::load(slip)) // read first: its wait overlaps the field's
#endif
  {
  }
  float direction(int c, float u) const
  {
    return this->K.buoyancy * u + this->Slip[c];
  }
  void step(const float dudt[3], const float along[3])
  {
    slipStep(this->K, dudt, along, this->Slip, this->Move);
  }
#if BOUNDPARTICLES_SSE2
  Lanes direction(Lanes u) const
  {
    return Lanes(this->K.buoyancy) * u + this->Held;
  }
  void step(Lanes dudt, Lanes along)
  {
    const Lanes gravity(_mm_setr_ps(this->K.gravity[0], this->K.gravity[1], this->K.gravity[2], 0));
    Lanes move;
    slipStepOf(this->K, gravity, dudt, along, this->Held, move);
    this->Held.store(this->Slip);
    move.store(this->Move);
  }
#endif

private:
  const InertiaStep& K;
  float* Slip;
  float* Move;
#if BOUNDPARTICLES_SSE2
  Lanes Held; ///< the slip, in lanes
#endif
};

/// A rigid element's particles move as one body: each takes the element's
/// mean slip (the springs' correction of the positions, in the velocities),
/// which never adds kinetic energy. `slips` holds n particles' slips.
inline void shareSlip(float* slips, std::size_t n)
{
  if (n < 2)
  {
    return;
  }
  float mean[3] = { 0, 0, 0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      mean[c] += slips[3 * i + c];
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    mean[c] /= float(n);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      slips[3 * i + c] = mean[c];
    }
  }
}

/// The speed at which gravity (less buoyancy) settles a particle in still
/// fluid: its terminal slip tau (1 - beta) |g|. 0 without inertia.
inline double terminalSettlingSpeed(const Parameters& p)
{
  if (!carriesInertia(p))
  {
    return 0.0;
  }
  const double g = std::sqrt(double(p.gravity[0]) * p.gravity[0] +
    double(p.gravity[1]) * p.gravity[1] + double(p.gravity[2]) * p.gravity[2]);
  return double(p.responseTime) * std::abs(1.0 - double(addedMassFactor(p.densityRatio))) * g;
}

/// How far gravity alone carries a particle in still fluid over `t` from
/// rest: its slip approaches the terminal speed as 1 - exp(-t / tau), so the
/// distance is free fall's for t far below tau and the terminal's for t far
/// above it.
inline double settlingDistance(const Parameters& p, double t)
{
  if (!(t > 0.0) || !carriesInertia(p))
  {
    return 0.0;
  }
  const double tau = p.responseTime;
  const double x = t / tau;
  if (x < 1e-3)
  {
    // tau (t - tau (1 - exp(-x))) = t^2 (1/2 - x/6 + ...): the difference
    // cancels as x -> 0, and tau times it would be noise (inertiaStepOf's S).
    return terminalSettlingSpeed(p) / tau * t * t * (0.5 - x / 6.0 + x * x / 24.0);
  }
  return terminalSettlingSpeed(p) * (t + tau * std::expm1(-x));
}

/// How long gravity alone takes to carry a particle `length` in still fluid
/// from rest (settlingDistance(p, t) = length); 0 where it does not carry it
/// (no inertia, no gravity, a neutrally buoyant particle) or the settings
/// are not finite (validate() refuses those).
inline double settlingTime(const Parameters& p, double length)
{
  const double terminal = terminalSettlingSpeed(p);
  if (!(length > 0.0) || !(terminal > 0.0) || !std::isfinite(terminal) || !std::isfinite(length))
  {
    return 0.0;
  }
  // Free fall is the fastest: t is at least sqrt(2 length / a), and at most
  // length / terminal + tau (the terminal's distance lags it by under tau).
  const double a = terminal / double(p.responseTime);
  double lo = std::sqrt(2.0 * length / a);
  double hi = lo;
  for (int k = 0; k < 2100 && settlingDistance(p, hi) < length; ++k)
  {
    lo = hi;
    hi *= 2.0;
  }
  for (int k = 0; k < 64 && lo < hi; ++k)
  {
    const double mid = 0.5 * (lo + hi);
    (settlingDistance(p, mid) < length ? lo : hi) = mid;
  }
  return std::isfinite(hi) ? hi : 0.0;
}

/// The speed gravity gives a particle in still fluid after `t` from rest:
/// the terminal settling speed times 1 - exp(-t / tau) (free fall's a t for
/// t far below tau).
inline double settlingSpeedAfter(const Parameters& p, double t)
{
  if (!(t > 0.0) || !carriesInertia(p))
  {
    return 0.0;
  }
  return -terminalSettlingSpeed(p) * std::expm1(-t / double(p.responseTime));
}

/// A step far above tau makes the trace nearly massless: the slip relaxes to
/// its terminal in under a thousandth of a step. The tracer notes it.
inline bool nearlyMassless(const Parameters& p, double h)
{
  return carriesInertia(p) && double(p.responseTime) < 1e-3 * h;
}

} // namespace bp

#endif
