#pragma once
// A GLSL stage as the interpreter runs it: straight-line operations on scalar registers, with
// GLSL's structured control flow kept as markers that the interpreter turns into lane masks.
//
// Every GLSL value is a run of scalar registers in one of four banks (float, int, uint, bool),
// its components in GLSL's order: a vector x, y, z, w; a matrix column by column; an array
// element by element; a struct member by member. An operation names the first register of each
// operand; composite operations (dot, matrix products, texture lookups) read and write
// consecutive registers. Functions are inlined, swizzles, constant indices and struct members
// are resolved to registers when the stage is built, so what is left to run is arithmetic,
// selects, moves and the masks of divergent control flow, exactly the operations of the
// hand-written translations (shading/glsl/), which the interpreter calls for each register.
//
// Nothing here depends on glslang: the front end (frontend/compile.h) builds a Program from
// GLSL source; the interpreter (interpreter/) runs one over any number type.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace qs::ir {

enum class Bank : std::uint8_t { Float, Int, Uint, Bool };
inline constexpr int kBanks = 4;
inline constexpr int kMaxClipDistances = 8;  // gl_ClipDistance's size (GL_MAX_CLIP_DISTANCES)

// The operations. Unless noted: d is the destination register, a, b, c the operands, all of
// the operation's banks (F: float, I: int, U: uint, B: bool), one component each.
#define QS_IR_OPERATIONS(X)                                                                          \
    /* moves and selects, in bank Instr::bank */                                                      \
    X(Mov)          /* d = a */                                                                       \
    X(Select)       /* d = B[a] ? b : c */                                                            \
    X(LoadIndexed)  /* d = a[I[b] * n] for I[b] in [0, count); else 0 (count: Instr::count) */         \
    X(StoreIndexed) /* d[I[b] * n] = a, lanes of the running mask whose index is in range */           \
    /* float arithmetic */                                                                            \
    X(FNeg) X(FAdd) X(FSub) X(FMul) X(FDiv) X(FMod) X(FMin) X(FMax) X(FClamp) X(FMix) X(FStep)         \
    X(FSmoothStep) X(FAbs) X(FSign) X(FFloor) X(FCeil) X(FTrunc) X(FRoundEven) X(FFract) X(FSqrt)      \
    X(FInverseSqrt) X(FExp) X(FLog) X(FExp2) X(FLog2) X(FPow) X(FSin) X(FCos) X(FTan) X(FAsin)         \
    X(FAcos) X(FAtan) X(FAtan2) X(FSinh) X(FCosh) X(FTanh) X(FAsinh) X(FAcosh) X(FAtanh)               \
    X(FRadians) X(FDegrees) X(FFma)                                                                   \
    X(FModf)        /* d = fract part, c (float) = whole part of a */                                 \
    X(FFrexp)       /* d = significand, c (int) = exponent of a */                                    \
    X(FLdexp)       /* d = a * 2^I[b] */                                                              \
    X(FMixBool)     /* d = B[c] ? b : a  (mix with a bool) */                                         \
    /* derivatives (quads and Dual2 only) */                                                          \
    X(FDdx) X(FDdy) X(FDdxFine) X(FDdyFine) X(FDdxCoarse) X(FDdyCoarse) X(FFwidth) X(FFwidthFine)      \
    X(FFwidthCoarse)                                                                                  \
    /* float comparisons and tests, into B[d] */                                                      \
    X(FLess) X(FLessEqual) X(FGreater) X(FGreaterEqual) X(FEqual) X(FNotEqual) X(FIsNan) X(FIsInf)     \
    /* int (and, in bank Uint, uint: Instr::bank says which) */                                       \
    X(INeg) X(IAdd) X(ISub) X(IMul) X(IDiv) X(IMod) X(IAnd) X(IOr) X(IXor) X(INot) X(IShl) X(IShr)     \
    X(IMin) X(IMax) X(IClamp) X(IAbs) X(ISign)                                                        \
    X(ILess) X(ILessEqual) X(IGreater) X(IGreaterEqual) X(IEqual) X(INotEqual)                        \
    X(IBitfieldExtract) X(IBitfieldInsert) X(IBitfieldReverse) X(IBitCount) X(IFindLsb) X(IFindMsb)   \
    X(IAddCarry)    /* d = a + b, c (uint) = carry */                                                 \
    X(ISubBorrow)   /* d = a - b, c (uint) = borrow */                                                \
    X(IMulExtended) /* d = high 32 bits of a * b, c = low 32 bits */                                  \
    /* bool */                                                                                        \
    X(BNot) X(BAnd) X(BOr) X(BXor) X(BEqual) X(BNotEqual)                                             \
    /* conversions: to bank of d, from the bank the name says */                                      \
    X(FloatFromInt) X(FloatFromUint) X(FloatFromBool) X(IntFromFloat) X(UintFromFloat)                \
    X(IntFromUint) X(UintFromInt) X(IntFromBool) X(UintFromBool) X(BoolFromFloat) X(BoolFromInt)      \
    X(BoolFromUint) X(FloatBitsToInt) X(FloatBitsToUint) X(IntBitsToFloat) X(UintBitsToFloat)         \
    /* composite float operations over n-component vectors in consecutive registers */                \
    X(Dot)          /* d = dot(a, b) */                                                               \
    X(Length)       /* d = length(a) */                                                               \
    X(Distance)     /* d = distance(a, b) */                                                          \
    X(Normalize)    /* d..d+n-1 = normalize(a) */                                                     \
    X(Cross)        /* d..d+2 = cross(a, b) */                                                        \
    X(Reflect)      /* d = reflect(a, b) */                                                           \
    X(Refract)      /* d = refract(a, b, c) (c: eta, one register) */                                  \
    X(FaceForward)  /* d = faceforward(a, b, c) */                                                    \
    X(MatTimesVec)  /* d (rows) = a (n columns of m rows) * b (n) */                                  \
    X(VecTimesMat)  /* d (n columns) = a (m) * b (n columns of m rows) */                             \
    X(MatTimesMat)  /* d = a (count columns of m rows) * b (n columns of count rows) */               \
    X(Determinant)  /* d = determinant(a), a n x n */                                                 \
    X(Inverse)      /* d = inverse(a), a n x n */                                                     \
    /* textures: sampler slot in Instr::count, coordinates in n (3 for a samplerCube's direction) */   \
    X(Texture)      /* d..d+3 = texture(s, a..) implicit level of detail */                           \
    X(TextureBias)  /* ... with bias F[b] */                                                          \
    X(TextureLod)   /* ... at level F[b] */                                                           \
    X(TextureGrad)  /* ... from the derivatives F[b..b+n-1] along x, F[b+n..b+2n-1] along y */         \
    X(TextureOffset)     /* as Texture, TextureBias, TextureLod, TextureGrad, with texel offsets */    \
    X(TextureBiasOffset) /*   I[c..c+n-1] added */                                                    \
    X(TextureLodOffset)                                                                               \
    X(TextureGradOffset) /* (m = 4, any of these eight: a shadow sampler's, A's n coordinates */      \
                         /*   followed by the reference value; d = the filtered comparisons) */       \
    X(TexelFetch)   /* d..d+3 = texelFetch(s, I[a..], I[b]) */                                        \
    X(TexelFetchOffset) /* ... at I[a..] + I[c..] */                                                  \
    X(TextureSize)  /* I[d..] = textureSize(s, I[b]) */                                               \
    X(TextureGather)       /* d..d+3 = textureGather(s, a..a+n-1, m): channel m of level 0's texels */ \
                           /*   (m = 4: a shadow sampler's, each compared with F[b]) */                \
    X(TextureGatherOffset) /* ... with texel offsets I[c], I[c+1] */                                   \
    X(TextureQueryLod)     /* d, d+1 = textureQueryLod(s, a..) */                                      \
    X(TextureQueryLevels)  /* I[d] = textureQueryLevels(s) */                                           \
    /* control flow: the running mask of lanes; jump targets in Instr::target */                      \
    X(If)           /* lanes of B[a] run the then-part; none: jump to target (Else or EndIf) */       \
    X(Else)         /* the other lanes run the else-part; none: jump to target (EndIf) */              \
    X(EndIf)                                                                                          \
    X(LoopBegin)    /* target: the LoopEnd */                                                         \
    X(LoopContinue) /* lanes that continued rejoin (before a for loop's increment) */                 \
    X(LoopEnd)      /* back to target (after the LoopBegin) while lanes run */                         \
    X(Break)        /* the running lanes leave the innermost loop or switch */                        \
    X(BreakUnless)  /* the running lanes with !B[a] leave the innermost loop */                       \
    X(Continue)                                                                                       \
    X(SwitchBegin) X(SwitchEnd)                                                                       \
    X(CallBegin)    /* an inlined function: its returning lanes are restored at CallEnd */             \
    X(CallEnd)                                                                                        \
    X(Return)       /* the running lanes leave the innermost function (or main) */                    \
    X(Discard)      /* the running lanes write no colour; they go on as helpers */                    \
    /* the interpreter's own marker, never the front end's */                                         \
    X(Native)       /* float lanes run compiled block `count` for the instructions up to target, */   \
                    /*   then go on there; other numbers run them (interpreter/native_blocks.h) */

enum class Op : std::uint16_t {
#define QS_IR_ENUM(name) name,
    QS_IR_OPERATIONS(QS_IR_ENUM)
#undef QS_IR_ENUM
};

// The operation's name, for listings and messages.
const char* name(Op op);

// Whether component k of the operation's result depends on component k of its operands alone
// (arithmetic, comparisons, conversions, moves, selects, derivatives): one such operation may
// run over n components (Instr::n, Instr::broadcast).
bool component_wise(Op op);

struct Instr {
    Op op;
    Bank bank = Bank::Float;     // of d, where the operation does not fix it
    bool masked = false;         // d is a variable: lanes outside the running mask keep it
    std::uint8_t n = 1;          // components, or columns
    std::uint8_t m = 1;          // rows
    std::uint16_t count = 0;     // elements (LoadIndexed, StoreIndexed), sampler slot, columns
    // A component-wise operation of n components runs them in order, component k writing d + k
    // and reading a + k, b + k, c + k, or the operand's one register where its bit is set here
    // (1: a, 2: b, 4: c): `v * s` over a vec4 is one operation.
    std::uint8_t broadcast = 0;
    std::uint32_t d = 0, a = 0, b = 0, c = 0;
    std::uint32_t target = 0;    // control flow: the instruction to jump to
    std::uint32_t line = 0;      // GLSL source line (1-based), for messages
};

// A register's value before the stage runs: a literal (the 32 bits of a float, int, uint, or
// 0/1 for a bool).
struct Constant {
    Bank bank;
    std::uint32_t reg;
    std::uint32_t bits;
};

// Where a register's value comes from, outside the stage: what the renderer provides.
enum class Source : std::uint8_t {
    UserUniform,   // word `index` of user uniform `slot` (Uniforms::user)
    Time,          // the `time` uniform
    TeximageSize,  // component `index` of the size of `teximage` in texels (the `dims` uniform)
    Transform,     // component `index` of transform `slot` (TransformUniform), column by column
    FragCoord,     // gl_FragCoord component `index`
    FrontFacing,   // gl_FrontFacing
    Varying,       // interpolated float `index` (fragment) / written float `index` (vertex)
    Attribute,     // component `index` of vertex attribute `slot` (Attribute)
    GenericAttribute,  // component `index` of generic vertex attribute `slot` (its location)
    VertexId,      // gl_VertexID
    Position,      // gl_Position component `index` (vertex output)
    ClipDistance,  // gl_ClipDistance[index] (vertex output)
    ClipVertex,    // gl_ClipVertex component `index` (vertex output)
    Color,         // the fragment colour, component `index` (fragment output)
};

// The vertex inputs quadshade's scenes provide (VertexIn, shading/batches.h).
enum class Attribute : std::uint8_t { Position, Normal, Color, Texcoord0, Texcoord1 };

// The matrices the renderer knows: GL's built-in ones as the reference sets them (the scene's
// model-view-projection as the projection, the model-view the identity), and the scene's own
// transforms a shader declares by name (scenes/shader_inputs.h).
enum class TransformUniform : std::uint8_t {
    ModelViewProjection,  // gl_ModelViewProjectionMatrix, mvp
    ModelView,            // gl_ModelViewMatrix
    Projection,           // gl_ProjectionMatrix
    Normal,               // gl_NormalMatrix
    Model,                // model
    View,                 // view
    SceneProjection,      // projection
    SceneNormal,          // normalMatrix
};

struct Binding {
    Source source;
    std::uint16_t slot = 0;
    std::uint16_t index = 0;
    Bank bank = Bank::Float;
    std::uint32_t reg = 0;
};

// A user uniform, one scalar, vector or matrix (arrays and structs are flattened into one per
// leaf, named as GL names them: "a[2]", "s.b").
struct Uniform {
    std::string name;
    Bank bank;
    int components;     // 1..16
    int columns = 1;    // matrices: columns; components / columns rows
    std::array<std::uint32_t, 16> initial{};  // the declaration's initializer, or zeros
};

// A sampler uniform: its name, its kind (2: sampler2D, 3: sampler3D, kCubeSampler: samplerCube),
// and whether it is a shadow sampler (sampler2DShadow, samplerCubeShadow), which reads a depth
// comparison texture.
inline constexpr int kCubeSampler = 6;  // glsl::kCubeDims: a cube map's six faces
struct Sampler {
    std::string name;
    int dims = 2;
    bool shadow = false;
};

struct Stage {
    std::uint64_t serial = 0;      // unique in the process: caches of a stage's registers key on it
    std::vector<Instr> code;
    std::array<std::uint32_t, kBanks> registers{};  // per bank
    std::vector<Constant> constants;
    std::vector<Binding> inputs;   // filled before the stage runs
    std::vector<Binding> outputs;  // read after it has run
    bool derivatives = false;      // takes dFdx/dFdy/fwidth, or a texture's implicit level of detail
    bool discards = false;
    bool loops = false;
};

// A vertex input bound to generic attributes (frontend/compile_options.h): `slots` consecutive
// locations from `location`, one per matrix column and array element, each `components` wide.
struct GenericAttribute {
    std::string name;
    int location = 0;
    int slots = 1;
    int components = 4;
    Bank bank = Bank::Float;
};

// A varying float of the interface between the stages.
struct Varying {
    std::string name;  // GLSL name (and component)
    bool flat = false;
    bool noperspective = false;  // interpolated linearly in the window
};

struct Program {
    int version = 110;
    Stage vertex, fragment;
    std::vector<Varying> varyings;  // Source::Varying index i on both sides
    std::vector<Uniform> uniforms;  // Source::UserUniform slot i
    std::vector<Sampler> samplers;  // Instr::count of texture operations
    bool reads_time = false;
    bool reads_frag_coord = false;
    bool reads_front_facing = false;
    std::vector<Attribute> attributes;  // the vertex inputs the vertex stage reads
    std::vector<GenericAttribute> generic_attributes;  // those bound to generic attributes
    bool reads_vertex_id = false;
};

}  // namespace qs::ir
