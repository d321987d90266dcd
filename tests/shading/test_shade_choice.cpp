// The one place that picks a draw's shader instantiation, for both renderers.
#include <catch2/catch.hpp>

#include "shading/shade_choice.h"

namespace qs {

TEST_CASE("a draw is shaded per pixel unless its shader or its texture takes derivatives", "[shade_choice]") {
    const Needs plain{.derivatives = false}, derivative{.derivatives = true};
    const ShadeRequest coarse{.derivatives = Derivatives::CoarseLower};

    DrawShading s = choose_shading(plain, false, coarse);
    CHECK(!s.quads);
    CHECK(s.mode.derivatives == Derivatives::None);

    s = choose_shading(plain, true, coarse);  // a mipmapped texture's level of detail needs quads
    CHECK(s.quads);
    CHECK(s.mode.derivatives == Derivatives::CoarseLower);

    s = choose_shading(derivative, false, coarse);
    CHECK(s.quads);
    CHECK(s.mode.derivatives == Derivatives::CoarseLower);

    s = choose_shading(plain, false, ShadeRequest{.general_path = true});
    CHECK(s.quads);
    CHECK(s.mode.derivatives == Derivatives::Fine);

    s = choose_shading(derivative, false, ShadeRequest{.derivatives = Derivatives::Analytic});
    CHECK(!s.quads);
    CHECK(s.mode.derivatives == Derivatives::Analytic);

    s = choose_shading(derivative, false, ShadeRequest{.derivatives = Derivatives::None});
    CHECK(s.quads);
    CHECK(s.mode.derivatives == Derivatives::Fine);
}

TEST_CASE("requests no instantiation honours are refused, not shaded another way", "[shade_choice]") {
    const Needs derivative{.derivatives = true};
    for (Derivatives rule : {Derivatives::CoarseLower, Derivatives::CoarseUpper}) {
        const ShadeRequest r{.derivatives = rule, .precision = Precision::Double};
        CHECK_THROWS_AS(check_supported(r), UnsupportedRequest);
        CHECK_THROWS_AS(choose_shading(derivative, false, r), UnsupportedRequest);
    }
    CHECK_THROWS_AS(check_supported({.derivatives = Derivatives::Analytic, .check_undefined = true}), UnsupportedRequest);
    CHECK_THROWS_AS(check_supported({.precision = Precision::Double, .check_undefined = true}), UnsupportedRequest);
    CHECK_NOTHROW(check_supported({.derivatives = Derivatives::Fine, .precision = Precision::Double}));
    CHECK_NOTHROW(check_supported({.derivatives = Derivatives::Analytic, .precision = Precision::Double}));
    CHECK_NOTHROW(check_supported({.derivatives = Derivatives::CoarseUpper, .check_undefined = true}));
}

}  // namespace qs
