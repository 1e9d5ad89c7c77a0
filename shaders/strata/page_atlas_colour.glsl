// The page-cache atlas of colour layers (RGBA16F: linear rgb x coverage, coverage).
uniform sampler2DArray strata_pageAtlasColour;
