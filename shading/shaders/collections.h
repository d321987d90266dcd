#pragma once
// The built-in shaders' collections (QUADSHADE_SHADERS_IN): the texts they translate, and the
// probes that check the renderer against Mesa. `quadshade shaders` lists and `quadshade gallery`
// draws the catalogue by collection, in this order of names; a sheet's file is named after the
// part before the colon (docs/gallery/gustavson.png, opengl-es-pixel-shaders-tutorial.png).
//
// The texts:
//  - Stefan Gustavson, "Procedural Textures in GLSL", in OpenGL Insights, Patrick Cozzi and
//    Christophe Riccio (eds.), CRC Press, 2012, https://openglinsights.com/. Figures, tables and
//    listings are numbered as in the chapter's preprint (Figure 1.1, Table 1.1, Listing 1.3).
//  - The ProcTexGen articles: a game developer's blog posts on procedural textures generated on
//    the GPU and baked into a mesh's UV atlas ("Jpeg Buoys Amidst a Sea of Text", "Short Skirt,
//    Long Jacket", "The Big Procedural Easy", "Procedual Terseness"), with the sample application
//    ProcTexGen.
//  - Notes on the book "Noise is Beautiful": hashes, Perlin and simplex noise, their derivatives,
//    multifractals, warping and scattering (sample: https://www.shadertoy.com/view/tfdXRB).
//  - Ricardo Rendon Cepeda, "OpenGL ES Pixel Shaders Tutorial", raywenderlich.com (now Kodeco),
//    2014, https://www.kodeco.com/2323-opengl-es-pixel-shaders-tutorial: its procedural textures
//    (square grid, smooth noise).
//  - Orion Lawlor, "Procedural Solid Texturing", lecture notes of CS 481/681, University of
//    Alaska Fairbanks, 2010 (its snippets ran in the course's NetRun).

#include <string_view>

namespace qs::shaders {

inline constexpr std::string_view kGustavson = "Gustavson: Procedural Textures in GLSL (OpenGL Insights, 2012)";
inline constexpr std::string_view kProcTexGen = "ProcTexGen: procedural textures baked into UV atlases (blog articles)";
inline constexpr std::string_view kNoiseIsBeautiful =
    "Noise is Beautiful: hashes, Perlin and simplex noise (notes on the book)";
inline constexpr std::string_view kOpenGlEsTutorial =
    "OpenGL ES Pixel Shaders Tutorial: procedural textures (Rendon Cepeda, 2014)";
inline constexpr std::string_view kLawlor = "Lawlor: Procedural Solid Texturing (course notes, 2010)";
inline constexpr std::string_view kProbes = "tests: probes of the renderer against Mesa";

}  // namespace qs::shaders
