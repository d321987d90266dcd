#pragma once
// LLVM's C interface as jit/ calls it, loaded from the shared library when the first blocks are
// compiled: the library is 117 MB, and a quadshade call that compiles none (--help, a catalogue
// shader) never maps it, so it starts in the time and memory it took before blocks were compiled.

#include <llvm-c/Core.h>
#include <llvm-c/Error.h>
#include <llvm-c/LLJIT.h>
#include <llvm-c/Orc.h>
#include <llvm-c/Target.h>
#include <llvm-c/TargetMachine.h>

namespace qs::jit {

// The functions jit/ calls, each a pointer of its declared type, named as LLVM names it.
#define QS_LLVM_FUNCTIONS(X)                                                                                       \
    X(LLVMAddAttributeAtIndex) X(LLVMAddFunction) X(LLVMAppendBasicBlockInContext) X(LLVMBuildAdd) X(LLVMBuildAnd) \
    X(LLVMBuildCall2) X(LLVMBuildFAdd) X(LLVMBuildFCmp) X(LLVMBuildFDiv) X(LLVMBuildFMul) X(LLVMBuildFNeg)          \
    X(LLVMBuildFSub) X(LLVMBuildGEP2) X(LLVMBuildICmp) X(LLVMBuildLoad2) X(LLVMBuildMul) X(LLVMBuildNot)           \
    X(LLVMBuildOr) X(LLVMBuildRetVoid) X(LLVMBuildSExt) X(LLVMBuildSIToFP) X(LLVMBuildSelect) X(LLVMBuildStore)    \
    X(LLVMBuildSub) X(LLVMBuildXor) X(LLVMConstInt) X(LLVMConstNull) X(LLVMConstReal) X(LLVMConstVector)           \
    X(LLVMConsumeError) X(LLVMCreateBuilderInContext) X(LLVMCreateEnumAttribute) X(LLVMCreateStringAttribute)     \
    X(LLVMCreateTargetMachine) X(LLVMGetEnumAttributeKindForName)                                                 \
    X(LLVMDisposeBuilder) X(LLVMDisposeErrorMessage) X(LLVMDisposeMessage) X(LLVMDisposeModule)                   \
    X(LLVMFloatTypeInContext) X(LLVMFunctionType) X(LLVMGetDefaultTargetTriple) X(LLVMGetErrorMessage)           \
    X(LLVMGetHostCPUFeatures) X(LLVMGetHostCPUName) X(LLVMGetIntrinsicDeclaration) X(LLVMGetParam)               \
    X(LLVMGetTargetFromTriple) X(LLVMInt32TypeInContext) X(LLVMInt64TypeInContext) X(LLVMIntrinsicGetType)       \
    X(LLVMLookupIntrinsicID) X(LLVMModuleCreateWithNameInContext) X(LLVMOrcCreateLLJIT)                          \
    X(LLVMOrcCreateLLJITBuilder) X(LLVMOrcCreateNewThreadSafeContext) X(LLVMOrcCreateNewThreadSafeModule)        \
    X(LLVMOrcDisposeLLJIT) X(LLVMOrcDisposeThreadSafeContext) X(LLVMOrcJITTargetMachineBuilderCreateFromTargetMachine) \
    X(LLVMOrcLLJITAddLLVMIRModule) X(LLVMOrcLLJITBuilderSetJITTargetMachineBuilder) X(LLVMOrcLLJITGetMainJITDylib) \
    X(LLVMOrcLLJITLookup) X(LLVMOrcThreadSafeContextGetContext) X(LLVMPointerType) X(LLVMPositionBuilderAtEnd)    \
    X(LLVMSetAlignment) X(LLVMVectorType) X(LLVMVoidTypeInContext)                                                 \
    /* this machine's code generator (llvm-c/Target.h's LLVMInitializeNativeTarget, spelled out) */                \
    X(LLVM_NATIVE_TARGETINFO) X(LLVM_NATIVE_TARGET) X(LLVM_NATIVE_TARGETMC) X(LLVM_NATIVE_ASMPRINTER)

struct LlvmApi {
#define QS_LLVM_POINTER(name) decltype(&::name) name = nullptr;
    QS_LLVM_FUNCTIONS(QS_LLVM_POINTER)
#undef QS_LLVM_POINTER
};

// The interface, loaded and this machine's code generator initialised on the first call. Throws
// JitError (compiled_blocks.h) naming the library or the function that is missing.
const LlvmApi& llvm();

}  // namespace qs::jit
