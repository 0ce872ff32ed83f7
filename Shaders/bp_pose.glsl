// Step 6 with Parameters::trackPoses, per element (Engine::updatePose,
// Core/Elements/Pose.h): the pose, the best rigid fit of the particles after the step
// warm-started from the pose before it, and the spin, the turn from the one
// to the other over the step, with the vorticity meter's reading against the
// curl of the field at the centre at the step's end. An element whose
// positions turned non-finite (it has its positions from before the step
// back) and a one-particle element keep their pose and get no spin.

// Element e, its particles after the step (bpPositionOf) and its state after
// the test: `pose`, the pose before the step (placed anew where reset),
// becomes the one after it; `spin` is the angular velocity and
// SpinVorticityRatio.
void bpPoseElement(int e, vec4 element, inout vec4 pose, out vec4 spin)
{
  if (element.w > 0.5 || bpParticles < 2)
  {
    spin = vec4(0.0);
    return;
  }
  vec4 before = pose;
  vec3 c, a0, a1, a2;
  bpMomentOf(e, c, a0, a1, a2);
  pose = bpFitRotation(a0, a1, a2, before, BP_POSE_ITERATIONS);
  vec3 w = bpSpinBetween(before, pose, bpStep);
  spin = vec4(w, bpSpinVorticityRatio(w, bpCurl(c, bpEndWeight), bpStep));
}

void bpPosePass(ivec2 texel, int e, int i, inout vec4 pose, inout vec4 spin,
  inout vec4 unused2, inout vec4 unused3)
{
  pose = texelFetch(bpPoses, texel, 0);
  bpPoseElement(e, texelFetch(bpElementState, texel, 0), pose, spin);
}
