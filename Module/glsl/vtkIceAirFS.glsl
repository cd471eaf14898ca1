//ICE::Dec
in vec2 iceAirUVVSOutput;
uniform sampler2D iceAirAtlas;      // bubble images (RGBA)
uniform sampler2D iceDepthInterval; // front (R) and back (G) view depth of the ice
uniform float iceMilkiness;         // 0: sparse clear bubbles, 1: white and cloudy
uniform int iceAirDebug;            // 1: solid green where a bubble covers
//ICE::Impl
  {
    vec2 interval = texelFetch(iceDepthInterval, iceScreenTexel(), 0).rg;
    float depth = iceViewDepth();
    if (depth < interval.x || depth > interval.y) { discard; }
    vec4 bubble = texture(iceAirAtlas, iceAirUVVSOutput);
    float alpha = clamp(bubble.a * mix(0.45, 1.6, iceMilkiness), 0.0, 1.0);
    vec3 colour = mix(bubble.rgb, vec3(1.0), iceMilkiness);
    if (iceAirDebug == 1)
    {
      if (bubble.a < 0.2) { discard; }
      colour = vec3(0.0, 1.0, 0.0);
      alpha = 1.0;
    }
    gl_FragData[0] = vec4(colour, alpha);
    // Seen where the ice's front surface is seen (see the crack shader).
    gl_FragDepth = iceWindowDepth(interval.x * 0.99);
  }
