// The page-cache atlas of one-channel layers (RGBA32F: value x coverage, coverage, and the value's slopes along slot
// x and y, page_value_slopes.comp).
uniform sampler2DArray strata_pageAtlasValues;
