  if (bpScalarMode != BP_COLOR_SOLID)
  {
    float bpU = clamp(bpScalarVSOutput, 0.0, 1.0);
    vec4 bpColor = texture(bpColorTable,
      vec2((bpU * (bpColorTableSize - 1.0) + 0.5) / bpColorTableSize, 0.5));
    ambientColor = ambientIntensity * bpColor.rgb;
    diffuseColor = diffuseIntensity * bpColor.rgb;
    opacity = opacity * bpColor.a;
  }
  opacity = opacity * bpFade;
