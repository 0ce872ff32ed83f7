// Step 6 with Parameters::trackPoses, per element (Engine::updatePose,
// Core/Pose.h): the pose, the best rigid fit of the particles after the step
// warm-started from the pose before it, and the spin, the turn from the one
// to the other over the step, with the vorticity meter's reading against the
// curl of the field at the centre at the step's end. An element whose
// positions turned non-finite (it has its positions from before the step
// back) and a one-particle element keep their pose and get no spin.
uniform sampler2D bpState;        // particles after the step (finalize)
uniform sampler2D bpElementState; // after the test pass: w, non-finite
uniform sampler2D bpPoses;        // before the step (placed anew where reset)
uniform sampler2D bpRest;
uniform float bpStep;      // float(h)
uniform float bpEndWeight; // the second time step's weight at t + h

layout(location = 0) out vec4 outPose;
layout(location = 1) out vec4 outSpin; // angular velocity, SpinVorticityRatio

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int e;
  if (!bpElementOf(texel, e))
  {
    outPose = vec4(0.0);
    outSpin = vec4(0.0);
    return;
  }
  vec4 before = texelFetch(bpPoses, texel, 0);
  if (texelFetch(bpElementState, texel, 0).w > 0.5 || bpParticles < 2)
  {
    outPose = before;
    outSpin = vec4(0.0);
    return;
  }
  vec3 c, a0, a1, a2;
  bpMomentOf(bpState, bpRest, e, c, a0, a1, a2);
  outPose = bpFitRotation(a0, a1, a2, before, BP_POSE_ITERATIONS);
  vec3 spin = bpSpinBetween(before, outPose, bpStep);
  outSpin = vec4(spin, bpSpinVorticityRatio(spin, bpCurl(c, bpEndWeight), bpStep));
}
