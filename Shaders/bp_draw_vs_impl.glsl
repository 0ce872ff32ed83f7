  // Bound particles: which particle of which element this vertex is.
  {
    int bpElement = gl_InstanceID;
    int bpParticle = gl_VertexID;
    if (bpDrawLinks != 0)
    {
      // Link gl_InstanceID joins particle i of its two elements, as the CPU
      // output's line cell does; drawn only when both elements are.
      ivec2 bpLink = texelFetch(bpLinks,
        ivec2(gl_InstanceID % bpLinksPerRow, gl_InstanceID / bpLinksPerRow), 0).xy;
      bpParticle = gl_VertexID / 2;
      bpElement = gl_VertexID % 2 == 0 ? bpLink.x : bpLink.y;
      bpHidden = bpHiddenElement(bpLink.x) || bpHiddenElement(bpLink.y);
    }
    else
    {
      bpHidden = bpHiddenElement(bpElement) || (bpTrail != 0 && bpNotInTrail(bpElement));
    }
    ivec2 bpTexel = bpParticleTexel(bpElement, bpParticle);
    vec4 bpState = texelFetch(bpPositions, bpTexel, 0);
    if (bpTrail != 0)
    {
      // A trail pose: the slot's position and the pose's own normal; the
      // colour scalar below is the element's now (but Age), as on the CPU.
      bpVertexMC = vec4(texelFetch(bpTrailPositions, bpTexel, 0).xyz, 1.0);
      bpNormalMC = bpTrailNormal(bpElement, bpParticle);
    }
    else
    {
      bpVertexMC = vec4(bpState.xyz, 1.0);
      bpNormalMC = texelFetch(bpNormals, bpTexel, 0).xyz;
    }
    float bpWidth = bpScalarRange.y - bpScalarRange.x;
    float bpScalar = bpScalarOf(bpElement, bpParticle, bpTexel, bpState);
    bpScalarVSOutput = bpWidth > 0.0 ? (bpScalar - bpScalarRange.x) / bpWidth : 0.5;
  }
