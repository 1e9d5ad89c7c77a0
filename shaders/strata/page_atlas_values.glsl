// The page-cache atlas of one-channel layers (RG32F: value x coverage, coverage).
uniform sampler2DArray strata_pageAtlasValues;
