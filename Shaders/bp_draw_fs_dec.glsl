// Drawing: the scalar colouring through the display's lookup table, sampled
// from a table texture as VTK does when it interpolates scalars before mapping.
in float bpScalarVSOutput;
uniform int bpScalarMode;
uniform sampler2D bpColorTable;
uniform float bpColorTableSize;
uniform float bpFade; // a trail pose's opacity factor: 1 on the elements
