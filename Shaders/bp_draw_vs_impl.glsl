  // Bound particles: this vertex is particle gl_VertexID of element gl_InstanceID.
  {
    ivec2 bpTexel = bpDrawTexel(gl_InstanceID, gl_VertexID);
    vec4 bpState = texelFetch(bpPositions, bpTexel, 0);
    bpVertexMC = vec4(bpState.xyz + bpOffset, 1.0);
    bpNormalMC = texelFetch(bpNormals, bpTexel, 0).xyz;
    float bpWidth = bpScalarRange.y - bpScalarRange.x;
    float bpScalar = bpScalarOf(gl_InstanceID, gl_VertexID, bpTexel, bpState);
    bpScalarVSOutput = bpWidth > 0.0 ? (bpScalar - bpScalarRange.x) / bpWidth : 0.5;
    ivec2 bpElementTexel = ivec2(gl_InstanceID % bpElementGrid.x, gl_InstanceID / bpElementGrid.x);
    bpHiddenVSOutput = texelFetch(bpCenters, bpElementTexel, 0).w;
  }
