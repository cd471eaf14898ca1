//ICE::Dec
// The back-face target of vtkIceBackfaceNormalPass, handed over by vtkIcePass: RGB the nearest
// back face's world normal, A its view depth (0: no ice). Declared here only; vtkIcePass inserts
// it before every part it fills that samples it.
uniform sampler2D iceBackNormals;
