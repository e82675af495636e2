

module texture_filter(clock,en,inp_valid,inp_words0_0,inp_words0_1,inp_words0_2,inp_words0_3,inp_words1_0,inp_words1_1,inp_words1_2,inp_words1_3,inp_alpha0,inp_beta0,inp_alpha1,inp_beta1,inp_frac,inp_two_levels,inp_format,inp_gaussian,inp_env,inp_cf,out_valid,out_rgba);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  inp_valid;
    input wire  [31:0] inp_words0_0;
    input wire  [31:0] inp_words0_1;
    input wire  [31:0] inp_words0_2;
    input wire  [31:0] inp_words0_3;
    input wire  [31:0] inp_words1_0;
    input wire  [31:0] inp_words1_1;
    input wire  [31:0] inp_words1_2;
    input wire  [31:0] inp_words1_3;
    input wire  [7:0] inp_alpha0;
    input wire  [7:0] inp_beta0;
    input wire  [7:0] inp_alpha1;
    input wire  [7:0] inp_beta1;
    input wire  [5:0] inp_frac;
    input wire  inp_two_levels;
    input wire  [2:0] inp_format;
    input wire  inp_gaussian;
    input wire  [2:0] inp_env;
    input wire  [23:0] inp_cf;
    output reg  out_valid;
    output reg  [31:0] out_rgba;
    
    // Constant declarations
    localparam  decal = 3'b10;
    
    // Stub signals
    reg  [31:0] decode$0$word;
    reg  [2:0] decode$0$format;
    wire  [31:0] decode$0$rgba;
    reg  [31:0] decode$1$word;
    reg  [2:0] decode$1$format;
    wire  [31:0] decode$1$rgba;
    reg  [31:0] decode$2$word;
    reg  [2:0] decode$2$format;
    wire  [31:0] decode$2$rgba;
    reg  [31:0] decode$3$word;
    reg  [2:0] decode$3$format;
    wire  [31:0] decode$3$rgba;
    reg  [31:0] decode$4$word;
    reg  [2:0] decode$4$format;
    wire  [31:0] decode$4$rgba;
    reg  [31:0] decode$5$word;
    reg  [2:0] decode$5$format;
    wire  [31:0] decode$5$rgba;
    reg  [31:0] decode$6$word;
    reg  [2:0] decode$6$format;
    wire  [31:0] decode$6$rgba;
    reg  [31:0] decode$7$word;
    reg  [2:0] decode$7$format;
    wire  [31:0] decode$7$rgba;
    reg  [7:0] weight$0$alpha;
    reg  weight$0$gaussian;
    wire  [8:0] weight$0$w;
    reg  [7:0] weight$1$alpha;
    reg  weight$1$gaussian;
    wire  [8:0] weight$1$w;
    reg  [7:0] weight$2$alpha;
    reg  weight$2$gaussian;
    wire  [8:0] weight$2$w;
    reg  [7:0] weight$3$alpha;
    reg  weight$3$gaussian;
    wire  [8:0] weight$3$w;
    reg  [31:0] s1_texel$0$d;
    wire  [31:0] s1_texel$0$q;
    reg  s1_texel$0$clock;
    reg  [31:0] s1_texel$1$d;
    wire  [31:0] s1_texel$1$q;
    reg  s1_texel$1$clock;
    reg  [31:0] s1_texel$2$d;
    wire  [31:0] s1_texel$2$q;
    reg  s1_texel$2$clock;
    reg  [31:0] s1_texel$3$d;
    wire  [31:0] s1_texel$3$q;
    reg  s1_texel$3$clock;
    reg  [31:0] s1_texel$4$d;
    wire  [31:0] s1_texel$4$q;
    reg  s1_texel$4$clock;
    reg  [31:0] s1_texel$5$d;
    wire  [31:0] s1_texel$5$q;
    reg  s1_texel$5$clock;
    reg  [31:0] s1_texel$6$d;
    wire  [31:0] s1_texel$6$q;
    reg  s1_texel$6$clock;
    reg  [31:0] s1_texel$7$d;
    wire  [31:0] s1_texel$7$q;
    reg  s1_texel$7$clock;
    reg  [8:0] s1_a$0$d;
    wire  [8:0] s1_a$0$q;
    reg  s1_a$0$clock;
    reg  [8:0] s1_a$1$d;
    wire  [8:0] s1_a$1$q;
    reg  s1_a$1$clock;
    reg  [8:0] s1_b$0$d;
    wire  [8:0] s1_b$0$q;
    reg  s1_b$0$clock;
    reg  [8:0] s1_b$1$d;
    wire  [8:0] s1_b$1$q;
    reg  s1_b$1$clock;
    reg  [5:0] s1_frac$d;
    wire  [5:0] s1_frac$q;
    reg  s1_frac$clock;
    reg  s1_two$d;
    wire  s1_two$q;
    reg  s1_two$clock;
    reg  [2:0] s1_env$d;
    wire  [2:0] s1_env$q;
    reg  s1_env$clock;
    reg  [23:0] s1_cf$d;
    wire  [23:0] s1_cf$q;
    reg  s1_cf$clock;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  level$0$clock;
    reg  level$0$en;
    reg  [31:0] level$0$t0;
    reg  [31:0] level$0$t1;
    reg  [31:0] level$0$t2;
    reg  [31:0] level$0$t3;
    reg  [8:0] level$0$a;
    reg  [8:0] level$0$b;
    wire  [31:0] level$0$c;
    reg  level$1$clock;
    reg  level$1$en;
    reg  [31:0] level$1$t0;
    reg  [31:0] level$1$t1;
    reg  [31:0] level$1$t2;
    reg  [31:0] level$1$t3;
    reg  [8:0] level$1$a;
    reg  [8:0] level$1$b;
    wire  [31:0] level$1$c;
    reg  [5:0] s2_frac$d;
    wire  [5:0] s2_frac$q;
    reg  s2_frac$clock;
    reg  s2_two$d;
    wire  s2_two$q;
    reg  s2_two$clock;
    reg  [2:0] s2_env$d;
    wire  [2:0] s2_env$q;
    reg  s2_env$clock;
    reg  [23:0] s2_cf$d;
    wire  [23:0] s2_cf$q;
    reg  s2_cf$clock;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  [5:0] s3_frac$d;
    wire  [5:0] s3_frac$q;
    reg  s3_frac$clock;
    reg  s3_two$d;
    wire  s3_two$q;
    reg  s3_two$clock;
    reg  [2:0] s3_env$d;
    wire  [2:0] s3_env$q;
    reg  s3_env$clock;
    reg  [23:0] s3_cf$d;
    wire  [23:0] s3_cf$q;
    reg  s3_cf$clock;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [7:0] mix$0$x0;
    reg  [7:0] mix$0$x1;
    reg  [6:0] mix$0$w;
    wire  [13:0] mix$0$y;
    reg  [7:0] mix$1$x0;
    reg  [7:0] mix$1$x1;
    reg  [6:0] mix$1$w;
    wire  [13:0] mix$1$y;
    reg  [7:0] mix$2$x0;
    reg  [7:0] mix$2$x1;
    reg  [6:0] mix$2$w;
    wire  [13:0] mix$2$y;
    reg  [7:0] mix$3$x0;
    reg  [7:0] mix$3$x1;
    reg  [6:0] mix$3$w;
    wire  [13:0] mix$3$y;
    reg  [13:0] mix_round$0$x;
    wire  [7:0] mix_round$0$y;
    reg  [13:0] mix_round$1$x;
    wire  [7:0] mix_round$1$y;
    reg  [13:0] mix_round$2$x;
    wire  [7:0] mix_round$2$y;
    reg  [13:0] mix_round$3$x;
    wire  [7:0] mix_round$3$y;
    reg  [7:0] s4_cs$0$d;
    wire  [7:0] s4_cs$0$q;
    reg  s4_cs$0$clock;
    reg  [7:0] s4_cs$1$d;
    wire  [7:0] s4_cs$1$q;
    reg  s4_cs$1$clock;
    reg  [7:0] s4_cs$2$d;
    wire  [7:0] s4_cs$2$q;
    reg  s4_cs$2$clock;
    reg  [7:0] s4_cs$3$d;
    wire  [7:0] s4_cs$3$q;
    reg  s4_cs$3$clock;
    reg  [2:0] s4_env$d;
    wire  [2:0] s4_env$q;
    reg  s4_env$clock;
    reg  [23:0] s4_cf$d;
    wire  [23:0] s4_cf$q;
    reg  s4_cf$clock;
    reg  s4_valid$d;
    wire  s4_valid$q;
    reg  s4_valid$clock;
    reg  [7:0] environment$0$cf;
    reg  [7:0] environment$0$cs;
    reg  [7:0] environment$0$a_s;
    reg  [2:0] environment$0$mode;
    wire  [7:0] environment$0$out;
    reg  [7:0] environment$1$cf;
    reg  [7:0] environment$1$cs;
    reg  [7:0] environment$1$a_s;
    reg  [2:0] environment$1$mode;
    wire  [7:0] environment$1$out;
    reg  [7:0] environment$2$cf;
    reg  [7:0] environment$2$cs;
    reg  [7:0] environment$2$a_s;
    reg  [2:0] environment$2$mode;
    wire  [7:0] environment$2$out;
    reg  [31:0] s5_rgba$d;
    wire  [31:0] s5_rgba$q;
    reg  s5_rgba$clock;
    reg  s5_valid$d;
    wire  s5_valid$q;
    reg  s5_valid$clock;
    
    // Local signals
    reg  [6:0] mix_w;
    reg  [7:0] alpha;
    
    // Sub module instances
    texture_filter$decode$0 decode$0(
        .word(decode$0$word),
        .format(decode$0$format),
        .rgba(decode$0$rgba)
    );
    texture_filter$decode$1 decode$1(
        .word(decode$1$word),
        .format(decode$1$format),
        .rgba(decode$1$rgba)
    );
    texture_filter$decode$2 decode$2(
        .word(decode$2$word),
        .format(decode$2$format),
        .rgba(decode$2$rgba)
    );
    texture_filter$decode$3 decode$3(
        .word(decode$3$word),
        .format(decode$3$format),
        .rgba(decode$3$rgba)
    );
    texture_filter$decode$4 decode$4(
        .word(decode$4$word),
        .format(decode$4$format),
        .rgba(decode$4$rgba)
    );
    texture_filter$decode$5 decode$5(
        .word(decode$5$word),
        .format(decode$5$format),
        .rgba(decode$5$rgba)
    );
    texture_filter$decode$6 decode$6(
        .word(decode$6$word),
        .format(decode$6$format),
        .rgba(decode$6$rgba)
    );
    texture_filter$decode$7 decode$7(
        .word(decode$7$word),
        .format(decode$7$format),
        .rgba(decode$7$rgba)
    );
    texture_filter$weight$0 weight$0(
        .alpha(weight$0$alpha),
        .gaussian(weight$0$gaussian),
        .w(weight$0$w)
    );
    texture_filter$weight$1 weight$1(
        .alpha(weight$1$alpha),
        .gaussian(weight$1$gaussian),
        .w(weight$1$w)
    );
    texture_filter$weight$2 weight$2(
        .alpha(weight$2$alpha),
        .gaussian(weight$2$gaussian),
        .w(weight$2$w)
    );
    texture_filter$weight$3 weight$3(
        .alpha(weight$3$alpha),
        .gaussian(weight$3$gaussian),
        .w(weight$3$w)
    );
    texture_filter$s1_texel$0 s1_texel$0(
        .d(s1_texel$0$d),
        .q(s1_texel$0$q),
        .clock(s1_texel$0$clock)
    );
    texture_filter$s1_texel$1 s1_texel$1(
        .d(s1_texel$1$d),
        .q(s1_texel$1$q),
        .clock(s1_texel$1$clock)
    );
    texture_filter$s1_texel$2 s1_texel$2(
        .d(s1_texel$2$d),
        .q(s1_texel$2$q),
        .clock(s1_texel$2$clock)
    );
    texture_filter$s1_texel$3 s1_texel$3(
        .d(s1_texel$3$d),
        .q(s1_texel$3$q),
        .clock(s1_texel$3$clock)
    );
    texture_filter$s1_texel$4 s1_texel$4(
        .d(s1_texel$4$d),
        .q(s1_texel$4$q),
        .clock(s1_texel$4$clock)
    );
    texture_filter$s1_texel$5 s1_texel$5(
        .d(s1_texel$5$d),
        .q(s1_texel$5$q),
        .clock(s1_texel$5$clock)
    );
    texture_filter$s1_texel$6 s1_texel$6(
        .d(s1_texel$6$d),
        .q(s1_texel$6$q),
        .clock(s1_texel$6$clock)
    );
    texture_filter$s1_texel$7 s1_texel$7(
        .d(s1_texel$7$d),
        .q(s1_texel$7$q),
        .clock(s1_texel$7$clock)
    );
    texture_filter$s1_a$0 s1_a$0(
        .d(s1_a$0$d),
        .q(s1_a$0$q),
        .clock(s1_a$0$clock)
    );
    texture_filter$s1_a$1 s1_a$1(
        .d(s1_a$1$d),
        .q(s1_a$1$q),
        .clock(s1_a$1$clock)
    );
    texture_filter$s1_b$0 s1_b$0(
        .d(s1_b$0$d),
        .q(s1_b$0$q),
        .clock(s1_b$0$clock)
    );
    texture_filter$s1_b$1 s1_b$1(
        .d(s1_b$1$d),
        .q(s1_b$1$q),
        .clock(s1_b$1$clock)
    );
    texture_filter$s1_frac s1_frac(
        .d(s1_frac$d),
        .q(s1_frac$q),
        .clock(s1_frac$clock)
    );
    texture_filter$s1_two s1_two(
        .d(s1_two$d),
        .q(s1_two$q),
        .clock(s1_two$clock)
    );
    texture_filter$s1_env s1_env(
        .d(s1_env$d),
        .q(s1_env$q),
        .clock(s1_env$clock)
    );
    texture_filter$s1_cf s1_cf(
        .d(s1_cf$d),
        .q(s1_cf$q),
        .clock(s1_cf$clock)
    );
    texture_filter$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    texture_filter$level$0 level$0(
        .clock(level$0$clock),
        .en(level$0$en),
        .t0(level$0$t0),
        .t1(level$0$t1),
        .t2(level$0$t2),
        .t3(level$0$t3),
        .a(level$0$a),
        .b(level$0$b),
        .c(level$0$c)
    );
    texture_filter$level$1 level$1(
        .clock(level$1$clock),
        .en(level$1$en),
        .t0(level$1$t0),
        .t1(level$1$t1),
        .t2(level$1$t2),
        .t3(level$1$t3),
        .a(level$1$a),
        .b(level$1$b),
        .c(level$1$c)
    );
    texture_filter$s2_frac s2_frac(
        .d(s2_frac$d),
        .q(s2_frac$q),
        .clock(s2_frac$clock)
    );
    texture_filter$s2_two s2_two(
        .d(s2_two$d),
        .q(s2_two$q),
        .clock(s2_two$clock)
    );
    texture_filter$s2_env s2_env(
        .d(s2_env$d),
        .q(s2_env$q),
        .clock(s2_env$clock)
    );
    texture_filter$s2_cf s2_cf(
        .d(s2_cf$d),
        .q(s2_cf$q),
        .clock(s2_cf$clock)
    );
    texture_filter$s2_valid s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    texture_filter$s3_frac s3_frac(
        .d(s3_frac$d),
        .q(s3_frac$q),
        .clock(s3_frac$clock)
    );
    texture_filter$s3_two s3_two(
        .d(s3_two$d),
        .q(s3_two$q),
        .clock(s3_two$clock)
    );
    texture_filter$s3_env s3_env(
        .d(s3_env$d),
        .q(s3_env$q),
        .clock(s3_env$clock)
    );
    texture_filter$s3_cf s3_cf(
        .d(s3_cf$d),
        .q(s3_cf$q),
        .clock(s3_cf$clock)
    );
    texture_filter$s3_valid s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    texture_filter$mix$0 mix$0(
        .x0(mix$0$x0),
        .x1(mix$0$x1),
        .w(mix$0$w),
        .y(mix$0$y)
    );
    texture_filter$mix$1 mix$1(
        .x0(mix$1$x0),
        .x1(mix$1$x1),
        .w(mix$1$w),
        .y(mix$1$y)
    );
    texture_filter$mix$2 mix$2(
        .x0(mix$2$x0),
        .x1(mix$2$x1),
        .w(mix$2$w),
        .y(mix$2$y)
    );
    texture_filter$mix$3 mix$3(
        .x0(mix$3$x0),
        .x1(mix$3$x1),
        .w(mix$3$w),
        .y(mix$3$y)
    );
    texture_filter$mix_round$0 mix_round$0(
        .x(mix_round$0$x),
        .y(mix_round$0$y)
    );
    texture_filter$mix_round$1 mix_round$1(
        .x(mix_round$1$x),
        .y(mix_round$1$y)
    );
    texture_filter$mix_round$2 mix_round$2(
        .x(mix_round$2$x),
        .y(mix_round$2$y)
    );
    texture_filter$mix_round$3 mix_round$3(
        .x(mix_round$3$x),
        .y(mix_round$3$y)
    );
    texture_filter$s4_cs$0 s4_cs$0(
        .d(s4_cs$0$d),
        .q(s4_cs$0$q),
        .clock(s4_cs$0$clock)
    );
    texture_filter$s4_cs$1 s4_cs$1(
        .d(s4_cs$1$d),
        .q(s4_cs$1$q),
        .clock(s4_cs$1$clock)
    );
    texture_filter$s4_cs$2 s4_cs$2(
        .d(s4_cs$2$d),
        .q(s4_cs$2$q),
        .clock(s4_cs$2$clock)
    );
    texture_filter$s4_cs$3 s4_cs$3(
        .d(s4_cs$3$d),
        .q(s4_cs$3$q),
        .clock(s4_cs$3$clock)
    );
    texture_filter$s4_env s4_env(
        .d(s4_env$d),
        .q(s4_env$q),
        .clock(s4_env$clock)
    );
    texture_filter$s4_cf s4_cf(
        .d(s4_cf$d),
        .q(s4_cf$q),
        .clock(s4_cf$clock)
    );
    texture_filter$s4_valid s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    texture_filter$environment$0 environment$0(
        .cf(environment$0$cf),
        .cs(environment$0$cs),
        .a_s(environment$0$a_s),
        .mode(environment$0$mode),
        .out(environment$0$out)
    );
    texture_filter$environment$1 environment$1(
        .cf(environment$1$cf),
        .cs(environment$1$cs),
        .a_s(environment$1$a_s),
        .mode(environment$1$mode),
        .out(environment$1$out)
    );
    texture_filter$environment$2 environment$2(
        .cf(environment$2$cf),
        .cs(environment$2$cs),
        .a_s(environment$2$a_s),
        .mode(environment$2$mode),
        .out(environment$2$out)
    );
    texture_filter$s5_rgba s5_rgba(
        .d(s5_rgba$d),
        .q(s5_rgba$q),
        .clock(s5_rgba$clock)
    );
    texture_filter$s5_valid s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    
    // Update code
    always @(*) begin
        s1_frac$clock = clock;
        s1_two$clock = clock;
        s1_env$clock = clock;
        s1_cf$clock = clock;
        s1_valid$clock = clock;
        s2_frac$clock = clock;
        s2_two$clock = clock;
        s2_env$clock = clock;
        s2_cf$clock = clock;
        s2_valid$clock = clock;
        s3_frac$clock = clock;
        s3_two$clock = clock;
        s3_env$clock = clock;
        s3_cf$clock = clock;
        s3_valid$clock = clock;
        s4_env$clock = clock;
        s4_cf$clock = clock;
        s4_valid$clock = clock;
        s5_rgba$clock = clock;
        s5_valid$clock = clock;
        s1_frac$d = s1_frac$q;
        s1_two$d = s1_two$q;
        s1_env$d = s1_env$q;
        s1_cf$d = s1_cf$q;
        s1_valid$d = s1_valid$q;
        s2_frac$d = s2_frac$q;
        s2_two$d = s2_two$q;
        s2_env$d = s2_env$q;
        s2_cf$d = s2_cf$q;
        s2_valid$d = s2_valid$q;
        s3_frac$d = s3_frac$q;
        s3_two$d = s3_two$q;
        s3_env$d = s3_env$q;
        s3_cf$d = s3_cf$q;
        s3_valid$d = s3_valid$q;
        s4_env$d = s4_env$q;
        s4_cf$d = s4_cf$q;
        s4_valid$d = s4_valid$q;
        s5_rgba$d = s5_rgba$q;
        s5_valid$d = s5_valid$q;
        s1_texel$0$clock = clock;
        s1_texel$0$d = s1_texel$0$q;
        s1_texel$1$clock = clock;
        s1_texel$1$d = s1_texel$1$q;
        s1_texel$2$clock = clock;
        s1_texel$2$d = s1_texel$2$q;
        s1_texel$3$clock = clock;
        s1_texel$3$d = s1_texel$3$q;
        s1_texel$4$clock = clock;
        s1_texel$4$d = s1_texel$4$q;
        s1_texel$5$clock = clock;
        s1_texel$5$d = s1_texel$5$q;
        s1_texel$6$clock = clock;
        s1_texel$6$d = s1_texel$6$q;
        s1_texel$7$clock = clock;
        s1_texel$7$d = s1_texel$7$q;
        s1_a$0$clock = clock;
        s1_a$0$d = s1_a$0$q;
        s1_b$0$clock = clock;
        s1_b$0$d = s1_b$0$q;
        level$0$clock = clock;
        level$0$en = en;
        s1_a$1$clock = clock;
        s1_a$1$d = s1_a$1$q;
        s1_b$1$clock = clock;
        s1_b$1$d = s1_b$1$q;
        level$1$clock = clock;
        level$1$en = en;
        s4_cs$0$clock = clock;
        s4_cs$0$d = s4_cs$0$q;
        s4_cs$1$clock = clock;
        s4_cs$1$d = s4_cs$1$q;
        s4_cs$2$clock = clock;
        s4_cs$2$d = s4_cs$2$q;
        s4_cs$3$clock = clock;
        s4_cs$3$d = s4_cs$3$q;
        decode$0$word = inp_words0_0;
        decode$1$word = inp_words0_1;
        decode$2$word = inp_words0_2;
        decode$3$word = inp_words0_3;
        decode$4$word = inp_words1_0;
        decode$5$word = inp_words1_1;
        decode$6$word = inp_words1_2;
        decode$7$word = inp_words1_3;
        decode$0$format = inp_format;
        decode$1$format = inp_format;
        decode$2$format = inp_format;
        decode$3$format = inp_format;
        decode$4$format = inp_format;
        decode$5$format = inp_format;
        decode$6$format = inp_format;
        decode$7$format = inp_format;
        weight$0$alpha = inp_alpha0;
        weight$1$alpha = inp_beta0;
        weight$2$alpha = inp_alpha1;
        weight$3$alpha = inp_beta1;
        weight$0$gaussian = inp_gaussian;
        weight$1$gaussian = inp_gaussian;
        weight$2$gaussian = inp_gaussian;
        weight$3$gaussian = inp_gaussian;
        level$0$a = s1_a$0$q;
        level$0$b = s1_b$0$q;
        level$1$a = s1_a$1$q;
        level$1$b = s1_b$1$q;
        level$0$t0 = s1_texel$0$q;
        level$0$t1 = s1_texel$1$q;
        level$0$t2 = s1_texel$2$q;
        level$0$t3 = s1_texel$3$q;
        level$1$t0 = s1_texel$4$q;
        level$1$t1 = s1_texel$5$q;
        level$1$t2 = s1_texel$6$q;
        level$1$t3 = s1_texel$7$q;
        mix_w = 32'h0;
        if (s3_two$q) begin
            mix_w = ((s3_frac$q) & 7'h7f);
        end
        mix$0$x0 = level$0$c[(0 * 32'h8)+:(8)];
        mix$0$x1 = level$1$c[(0 * 32'h8)+:(8)];
        mix$0$w = mix_w;
        mix_round$0$x = mix$0$y;
        mix$1$x0 = level$0$c[(1 * 32'h8)+:(8)];
        mix$1$x1 = level$1$c[(1 * 32'h8)+:(8)];
        mix$1$w = mix_w;
        mix_round$1$x = mix$1$y;
        mix$2$x0 = level$0$c[(2 * 32'h8)+:(8)];
        mix$2$x1 = level$1$c[(2 * 32'h8)+:(8)];
        mix$2$w = mix_w;
        mix_round$2$x = mix$2$y;
        mix$3$x0 = level$0$c[(3 * 32'h8)+:(8)];
        mix$3$x1 = level$1$c[(3 * 32'h8)+:(8)];
        mix$3$w = mix_w;
        mix_round$3$x = mix$3$y;
        environment$0$cf = s4_cf$q[(32'h10)+:(8)];
        environment$0$cs = s4_cs$3$q;
        environment$1$cf = s4_cf$q[(32'h8)+:(8)];
        environment$1$cs = s4_cs$2$q;
        environment$2$cf = s4_cf$q[(32'h0)+:(8)];
        environment$2$cs = s4_cs$1$q;
        environment$0$a_s = s4_cs$0$q;
        environment$0$mode = s4_env$q;
        environment$1$a_s = s4_cs$0$q;
        environment$1$mode = s4_env$q;
        environment$2$a_s = s4_cs$0$q;
        environment$2$mode = s4_env$q;
        alpha = s4_cs$0$q;
        if (s4_env$q == decal) begin
            alpha = 32'hff;
        end
        if (en) begin
            s1_texel$0$d = decode$0$rgba;
            s1_texel$1$d = decode$1$rgba;
            s1_texel$2$d = decode$2$rgba;
            s1_texel$3$d = decode$3$rgba;
            s1_texel$4$d = decode$4$rgba;
            s1_texel$5$d = decode$5$rgba;
            s1_texel$6$d = decode$6$rgba;
            s1_texel$7$d = decode$7$rgba;
            s1_a$0$d = weight$0$w;
            s1_b$0$d = weight$1$w;
            s1_a$1$d = weight$2$w;
            s1_b$1$d = weight$3$w;
            s1_frac$d = inp_frac;
            s1_two$d = inp_two_levels;
            s1_env$d = inp_env;
            s1_cf$d = inp_cf;
            s1_valid$d = inp_valid;
            s2_frac$d = s1_frac$q;
            s2_two$d = s1_two$q;
            s2_env$d = s1_env$q;
            s2_cf$d = s1_cf$q;
            s2_valid$d = s1_valid$q;
            s3_frac$d = s2_frac$q;
            s3_two$d = s2_two$q;
            s3_env$d = s2_env$q;
            s3_cf$d = s2_cf$q;
            s3_valid$d = s2_valid$q;
            s4_cs$0$d = mix_round$0$y;
            s4_cs$1$d = mix_round$1$y;
            s4_cs$2$d = mix_round$2$y;
            s4_cs$3$d = mix_round$3$y;
            s4_env$d = s3_env$q;
            s4_cf$d = s3_cf$q;
            s4_valid$d = s3_valid$q;
            s5_rgba$d = (((environment$0$out) & 32'hffffffff) << 32'h18) | (((environment$1$out) & 32'hffffffff) << 32'h10) | (((environment$2$out) & 32'hffffffff) << 32'h8) | ((alpha) & 32'hffffffff);
            s5_valid$d = s4_valid$q;
        end
        out_valid = s5_valid$q;
        out_rgba = s5_rgba$q;
    end
    
endmodule // texture_filter


module texture_filter$decode$0(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_filter$decode$0


module texture_filter$decode$1(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_filter$decode$1


module texture_filter$decode$2(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_filter$decode$2


module texture_filter$decode$3(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_filter$decode$3


module texture_filter$decode$4(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_filter$decode$4


module texture_filter$decode$5(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_filter$decode$5


module texture_filter$decode$6(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_filter$decode$6


module texture_filter$decode$7(word,format,rgba);
    
    // Module arguments
    input wire  [31:0] word;
    input wire  [2:0] format;
    output reg  [31:0] rgba;
    
    // Constant declarations
    localparam  rgb565 = 3'b0;
    localparam  rgba5551 = 3'b1;
    localparam  rgba4444 = 3'b10;
    localparam  rgb888 = 3'b11;
    
    // Local signals
    reg  [4:0] c5r;
    reg  [4:0] c5g;
    reg  [5:0] c6g;
    reg  [7:0] r;
    reg  [7:0] g;
    reg  [7:0] b;
    reg  [7:0] a;
    
    // Update code
    always @(*) begin
        c5r = word[(32'hb)+:(5)];
        c5g = word[(32'h6)+:(5)];
        c6g = word[(32'h5)+:(6)];
        r = word[(32'h18)+:(8)];
        g = word[(32'h10)+:(8)];
        b = word[(32'h8)+:(8)];
        a = word[(32'h0)+:(8)];
        if (format == rgb565) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c6g) & 8'hff) << 32'h2) | ((c6g[(32'h4)+:(2)]) & 8'hff);
            b = (((word[(32'h0)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h2)+:(3)]) & 8'hff);
            a = 32'hff;
        end
        if (format == rgba5551) begin
            r = (((c5r) & 8'hff) << 32'h3) | ((c5r[(32'h2)+:(3)]) & 8'hff);
            g = (((c5g) & 8'hff) << 32'h3) | ((c5g[(32'h2)+:(3)]) & 8'hff);
            b = (((word[(32'h1)+:(5)]) & 8'hff) << 32'h3) | ((word[(32'h3)+:(3)]) & 8'hff);
            a = 32'h0;
            if (word[32'h0]) begin
                a = 32'hff;
            end
        end
        if (format == rgba4444) begin
            r = (((word[(32'hc)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'hc)+:(4)]) & 8'hff);
            g = (((word[(32'h8)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h8)+:(4)]) & 8'hff);
            b = (((word[(32'h4)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h4)+:(4)]) & 8'hff);
            a = (((word[(32'h0)+:(4)]) & 8'hff) << 32'h4) | ((word[(32'h0)+:(4)]) & 8'hff);
        end
        if (format == rgb888) begin
            r = word[(32'h10)+:(8)];
            g = word[(32'h8)+:(8)];
            b = word[(32'h0)+:(8)];
            a = 32'hff;
        end
        rgba = (((r) & 32'hffffffff) << 32'h18) | (((g) & 32'hffffffff) << 32'h10) | (((b) & 32'hffffffff) << 32'h8) | ((a) & 32'hffffffff);
    end
    
endmodule // texture_filter$decode$7


module texture_filter$environment$0(cf,cs,a_s,mode,out);
    
    // Module arguments
    input wire  [7:0] cf;
    input wire  [7:0] cs;
    input wire  [7:0] a_s;
    input wire  [2:0] mode;
    output reg  [7:0] out;
    
    // Constant declarations
    localparam  modulate = 3'b1;
    localparam  decal = 3'b10;
    localparam  blend = 3'b11;
    localparam  add = 3'b100;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [8:0] mul$b;
    wire  [16:0] mul$p;
    
    // Local signals
    reg  [16:0] prod;
    reg  [16:0] biased;
    reg  [7:0] rounded;
    reg  [8:0] sum;
    reg  [7:0] inv_cs;
    reg  [16:0] base;
    
    // Sub module instances
    texture_filter$environment$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        base = 32'h0;
        mul$a = ((cf) & 9'h1ff);
        mul$b = ((cs) & 9'h1ff);
        inv_cs = ~cs;
        if (mode == blend) begin
            mul$b = ((inv_cs) & 9'h1ff);
        end
        if (mode == decal) begin
            base = (((cf) & 17'h1ffff) << 32'h8) - ((cf) & 17'h1ffff);
            mul$a = ((cs) & 9'h1ff) - ((cf) & 9'h1ff);
            mul$b = ((a_s) & 9'h1ff);
        end
        prod = base + mul$p;
        biased = prod + 32'h80;
        rounded = (((biased + (biased >> 32'h8)) >> 32'h8) & 8'hff);
        sum = ((cf) & 9'h1ff) + ((cs) & 9'h1ff);
        out = cs;
        if ((mode == modulate) | (mode == decal) | (mode == blend)) begin
            out = rounded;
        end
        if (mode == add) begin
            out = sum[(32'h0)+:(8)];
            if (sum[32'h8]) begin
                out = 32'hff;
            end
        end
    end
    
endmodule // texture_filter$environment$0


module texture_filter$environment$0$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$environment$0$mul


module texture_filter$environment$1(cf,cs,a_s,mode,out);
    
    // Module arguments
    input wire  [7:0] cf;
    input wire  [7:0] cs;
    input wire  [7:0] a_s;
    input wire  [2:0] mode;
    output reg  [7:0] out;
    
    // Constant declarations
    localparam  modulate = 3'b1;
    localparam  decal = 3'b10;
    localparam  blend = 3'b11;
    localparam  add = 3'b100;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [8:0] mul$b;
    wire  [16:0] mul$p;
    
    // Local signals
    reg  [16:0] prod;
    reg  [16:0] biased;
    reg  [7:0] rounded;
    reg  [8:0] sum;
    reg  [7:0] inv_cs;
    reg  [16:0] base;
    
    // Sub module instances
    texture_filter$environment$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        base = 32'h0;
        mul$a = ((cf) & 9'h1ff);
        mul$b = ((cs) & 9'h1ff);
        inv_cs = ~cs;
        if (mode == blend) begin
            mul$b = ((inv_cs) & 9'h1ff);
        end
        if (mode == decal) begin
            base = (((cf) & 17'h1ffff) << 32'h8) - ((cf) & 17'h1ffff);
            mul$a = ((cs) & 9'h1ff) - ((cf) & 9'h1ff);
            mul$b = ((a_s) & 9'h1ff);
        end
        prod = base + mul$p;
        biased = prod + 32'h80;
        rounded = (((biased + (biased >> 32'h8)) >> 32'h8) & 8'hff);
        sum = ((cf) & 9'h1ff) + ((cs) & 9'h1ff);
        out = cs;
        if ((mode == modulate) | (mode == decal) | (mode == blend)) begin
            out = rounded;
        end
        if (mode == add) begin
            out = sum[(32'h0)+:(8)];
            if (sum[32'h8]) begin
                out = 32'hff;
            end
        end
    end
    
endmodule // texture_filter$environment$1


module texture_filter$environment$1$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$environment$1$mul


module texture_filter$environment$2(cf,cs,a_s,mode,out);
    
    // Module arguments
    input wire  [7:0] cf;
    input wire  [7:0] cs;
    input wire  [7:0] a_s;
    input wire  [2:0] mode;
    output reg  [7:0] out;
    
    // Constant declarations
    localparam  modulate = 3'b1;
    localparam  decal = 3'b10;
    localparam  blend = 3'b11;
    localparam  add = 3'b100;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [8:0] mul$b;
    wire  [16:0] mul$p;
    
    // Local signals
    reg  [16:0] prod;
    reg  [16:0] biased;
    reg  [7:0] rounded;
    reg  [8:0] sum;
    reg  [7:0] inv_cs;
    reg  [16:0] base;
    
    // Sub module instances
    texture_filter$environment$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        base = 32'h0;
        mul$a = ((cf) & 9'h1ff);
        mul$b = ((cs) & 9'h1ff);
        inv_cs = ~cs;
        if (mode == blend) begin
            mul$b = ((inv_cs) & 9'h1ff);
        end
        if (mode == decal) begin
            base = (((cf) & 17'h1ffff) << 32'h8) - ((cf) & 17'h1ffff);
            mul$a = ((cs) & 9'h1ff) - ((cf) & 9'h1ff);
            mul$b = ((a_s) & 9'h1ff);
        end
        prod = base + mul$p;
        biased = prod + 32'h80;
        rounded = (((biased + (biased >> 32'h8)) >> 32'h8) & 8'hff);
        sum = ((cf) & 9'h1ff) + ((cs) & 9'h1ff);
        out = cs;
        if ((mode == modulate) | (mode == decal) | (mode == blend)) begin
            out = rounded;
        end
        if (mode == add) begin
            out = sum[(32'h0)+:(8)];
            if (sum[32'h8]) begin
                out = 32'hff;
            end
        end
    end
    
endmodule // texture_filter$environment$2


module texture_filter$environment$2$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$environment$2$mul


module texture_filter$level$0(clock,en,t0,t1,t2,t3,a,b,c);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [31:0] t0;
    input wire  [31:0] t1;
    input wire  [31:0] t2;
    input wire  [31:0] t3;
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [31:0] c;
    
    // Stub signals
    reg  [7:0] h$0$x0;
    reg  [7:0] h$0$x1;
    reg  [8:0] h$0$w;
    wire  [15:0] h$0$y;
    reg  [7:0] h$1$x0;
    reg  [7:0] h$1$x1;
    reg  [8:0] h$1$w;
    wire  [15:0] h$1$y;
    reg  [7:0] h$2$x0;
    reg  [7:0] h$2$x1;
    reg  [8:0] h$2$w;
    wire  [15:0] h$2$y;
    reg  [7:0] h$3$x0;
    reg  [7:0] h$3$x1;
    reg  [8:0] h$3$w;
    wire  [15:0] h$3$y;
    reg  [7:0] h$4$x0;
    reg  [7:0] h$4$x1;
    reg  [8:0] h$4$w;
    wire  [15:0] h$4$y;
    reg  [7:0] h$5$x0;
    reg  [7:0] h$5$x1;
    reg  [8:0] h$5$w;
    wire  [15:0] h$5$y;
    reg  [7:0] h$6$x0;
    reg  [7:0] h$6$x1;
    reg  [8:0] h$6$w;
    wire  [15:0] h$6$y;
    reg  [7:0] h$7$x0;
    reg  [7:0] h$7$x1;
    reg  [8:0] h$7$w;
    wire  [15:0] h$7$y;
    reg  [15:0] h_r$0$d;
    wire  [15:0] h_r$0$q;
    reg  h_r$0$clock;
    reg  [15:0] h_r$1$d;
    wire  [15:0] h_r$1$q;
    reg  h_r$1$clock;
    reg  [15:0] h_r$2$d;
    wire  [15:0] h_r$2$q;
    reg  h_r$2$clock;
    reg  [15:0] h_r$3$d;
    wire  [15:0] h_r$3$q;
    reg  h_r$3$clock;
    reg  [15:0] h_r$4$d;
    wire  [15:0] h_r$4$q;
    reg  h_r$4$clock;
    reg  [15:0] h_r$5$d;
    wire  [15:0] h_r$5$q;
    reg  h_r$5$clock;
    reg  [15:0] h_r$6$d;
    wire  [15:0] h_r$6$q;
    reg  h_r$6$clock;
    reg  [15:0] h_r$7$d;
    wire  [15:0] h_r$7$q;
    reg  h_r$7$clock;
    reg  [8:0] b_r$d;
    wire  [8:0] b_r$q;
    reg  b_r$clock;
    reg  [15:0] v$0$x0;
    reg  [15:0] v$0$x1;
    reg  [8:0] v$0$w;
    wire  [23:0] v$0$y;
    reg  [15:0] v$1$x0;
    reg  [15:0] v$1$x1;
    reg  [8:0] v$1$w;
    wire  [23:0] v$1$y;
    reg  [15:0] v$2$x0;
    reg  [15:0] v$2$x1;
    reg  [8:0] v$2$w;
    wire  [23:0] v$2$y;
    reg  [15:0] v$3$x0;
    reg  [15:0] v$3$x1;
    reg  [8:0] v$3$w;
    wire  [23:0] v$3$y;
    reg  [23:0] round$0$x;
    wire  [7:0] round$0$y;
    reg  [23:0] round$1$x;
    wire  [7:0] round$1$y;
    reg  [23:0] round$2$x;
    wire  [7:0] round$2$y;
    reg  [23:0] round$3$x;
    wire  [7:0] round$3$y;
    reg  [7:0] c_r$0$d;
    wire  [7:0] c_r$0$q;
    reg  c_r$0$clock;
    reg  [7:0] c_r$1$d;
    wire  [7:0] c_r$1$q;
    reg  c_r$1$clock;
    reg  [7:0] c_r$2$d;
    wire  [7:0] c_r$2$q;
    reg  c_r$2$clock;
    reg  [7:0] c_r$3$d;
    wire  [7:0] c_r$3$q;
    reg  c_r$3$clock;
    
    // Sub module instances
    texture_filter$level$0$h$0 h$0(
        .x0(h$0$x0),
        .x1(h$0$x1),
        .w(h$0$w),
        .y(h$0$y)
    );
    texture_filter$level$0$h$1 h$1(
        .x0(h$1$x0),
        .x1(h$1$x1),
        .w(h$1$w),
        .y(h$1$y)
    );
    texture_filter$level$0$h$2 h$2(
        .x0(h$2$x0),
        .x1(h$2$x1),
        .w(h$2$w),
        .y(h$2$y)
    );
    texture_filter$level$0$h$3 h$3(
        .x0(h$3$x0),
        .x1(h$3$x1),
        .w(h$3$w),
        .y(h$3$y)
    );
    texture_filter$level$0$h$4 h$4(
        .x0(h$4$x0),
        .x1(h$4$x1),
        .w(h$4$w),
        .y(h$4$y)
    );
    texture_filter$level$0$h$5 h$5(
        .x0(h$5$x0),
        .x1(h$5$x1),
        .w(h$5$w),
        .y(h$5$y)
    );
    texture_filter$level$0$h$6 h$6(
        .x0(h$6$x0),
        .x1(h$6$x1),
        .w(h$6$w),
        .y(h$6$y)
    );
    texture_filter$level$0$h$7 h$7(
        .x0(h$7$x0),
        .x1(h$7$x1),
        .w(h$7$w),
        .y(h$7$y)
    );
    texture_filter$level$0$h_r$0 h_r$0(
        .d(h_r$0$d),
        .q(h_r$0$q),
        .clock(h_r$0$clock)
    );
    texture_filter$level$0$h_r$1 h_r$1(
        .d(h_r$1$d),
        .q(h_r$1$q),
        .clock(h_r$1$clock)
    );
    texture_filter$level$0$h_r$2 h_r$2(
        .d(h_r$2$d),
        .q(h_r$2$q),
        .clock(h_r$2$clock)
    );
    texture_filter$level$0$h_r$3 h_r$3(
        .d(h_r$3$d),
        .q(h_r$3$q),
        .clock(h_r$3$clock)
    );
    texture_filter$level$0$h_r$4 h_r$4(
        .d(h_r$4$d),
        .q(h_r$4$q),
        .clock(h_r$4$clock)
    );
    texture_filter$level$0$h_r$5 h_r$5(
        .d(h_r$5$d),
        .q(h_r$5$q),
        .clock(h_r$5$clock)
    );
    texture_filter$level$0$h_r$6 h_r$6(
        .d(h_r$6$d),
        .q(h_r$6$q),
        .clock(h_r$6$clock)
    );
    texture_filter$level$0$h_r$7 h_r$7(
        .d(h_r$7$d),
        .q(h_r$7$q),
        .clock(h_r$7$clock)
    );
    texture_filter$level$0$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    texture_filter$level$0$v$0 v$0(
        .x0(v$0$x0),
        .x1(v$0$x1),
        .w(v$0$w),
        .y(v$0$y)
    );
    texture_filter$level$0$v$1 v$1(
        .x0(v$1$x0),
        .x1(v$1$x1),
        .w(v$1$w),
        .y(v$1$y)
    );
    texture_filter$level$0$v$2 v$2(
        .x0(v$2$x0),
        .x1(v$2$x1),
        .w(v$2$w),
        .y(v$2$y)
    );
    texture_filter$level$0$v$3 v$3(
        .x0(v$3$x0),
        .x1(v$3$x1),
        .w(v$3$w),
        .y(v$3$y)
    );
    texture_filter$level$0$round$0 round$0(
        .x(round$0$x),
        .y(round$0$y)
    );
    texture_filter$level$0$round$1 round$1(
        .x(round$1$x),
        .y(round$1$y)
    );
    texture_filter$level$0$round$2 round$2(
        .x(round$2$x),
        .y(round$2$y)
    );
    texture_filter$level$0$round$3 round$3(
        .x(round$3$x),
        .y(round$3$y)
    );
    texture_filter$level$0$c_r$0 c_r$0(
        .d(c_r$0$d),
        .q(c_r$0$q),
        .clock(c_r$0$clock)
    );
    texture_filter$level$0$c_r$1 c_r$1(
        .d(c_r$1$d),
        .q(c_r$1$q),
        .clock(c_r$1$clock)
    );
    texture_filter$level$0$c_r$2 c_r$2(
        .d(c_r$2$d),
        .q(c_r$2$q),
        .clock(c_r$2$clock)
    );
    texture_filter$level$0$c_r$3 c_r$3(
        .d(c_r$3$d),
        .q(c_r$3$q),
        .clock(c_r$3$clock)
    );
    
    // Update code
    always @(*) begin
        b_r$clock = clock;
        b_r$d = b_r$q;
        h_r$0$clock = clock;
        h_r$0$d = h_r$0$q;
        h_r$1$clock = clock;
        h_r$1$d = h_r$1$q;
        h_r$2$clock = clock;
        h_r$2$d = h_r$2$q;
        h_r$3$clock = clock;
        h_r$3$d = h_r$3$q;
        h_r$4$clock = clock;
        h_r$4$d = h_r$4$q;
        h_r$5$clock = clock;
        h_r$5$d = h_r$5$q;
        h_r$6$clock = clock;
        h_r$6$d = h_r$6$q;
        h_r$7$clock = clock;
        h_r$7$d = h_r$7$q;
        c_r$0$clock = clock;
        c_r$0$d = c_r$0$q;
        c_r$1$clock = clock;
        c_r$1$d = c_r$1$q;
        c_r$2$clock = clock;
        c_r$2$d = c_r$2$q;
        c_r$3$clock = clock;
        c_r$3$d = c_r$3$q;
        h$0$x0 = t0[(0 * 32'h8)+:(8)];
        h$0$x1 = t1[(0 * 32'h8)+:(8)];
        h$0$w = a;
        h$4$x0 = t2[(0 * 32'h8)+:(8)];
        h$4$x1 = t3[(0 * 32'h8)+:(8)];
        h$4$w = a;
        v$0$x0 = h_r$0$q;
        v$0$x1 = h_r$4$q;
        v$0$w = b_r$q;
        round$0$x = v$0$y;
        h$1$x0 = t0[(1 * 32'h8)+:(8)];
        h$1$x1 = t1[(1 * 32'h8)+:(8)];
        h$1$w = a;
        h$5$x0 = t2[(1 * 32'h8)+:(8)];
        h$5$x1 = t3[(1 * 32'h8)+:(8)];
        h$5$w = a;
        v$1$x0 = h_r$1$q;
        v$1$x1 = h_r$5$q;
        v$1$w = b_r$q;
        round$1$x = v$1$y;
        h$2$x0 = t0[(2 * 32'h8)+:(8)];
        h$2$x1 = t1[(2 * 32'h8)+:(8)];
        h$2$w = a;
        h$6$x0 = t2[(2 * 32'h8)+:(8)];
        h$6$x1 = t3[(2 * 32'h8)+:(8)];
        h$6$w = a;
        v$2$x0 = h_r$2$q;
        v$2$x1 = h_r$6$q;
        v$2$w = b_r$q;
        round$2$x = v$2$y;
        h$3$x0 = t0[(3 * 32'h8)+:(8)];
        h$3$x1 = t1[(3 * 32'h8)+:(8)];
        h$3$w = a;
        h$7$x0 = t2[(3 * 32'h8)+:(8)];
        h$7$x1 = t3[(3 * 32'h8)+:(8)];
        h$7$w = a;
        v$3$x0 = h_r$3$q;
        v$3$x1 = h_r$7$q;
        v$3$w = b_r$q;
        round$3$x = v$3$y;
        if (en) begin
            h_r$0$d = h$0$y;
            h_r$1$d = h$1$y;
            h_r$2$d = h$2$y;
            h_r$3$d = h$3$y;
            h_r$4$d = h$4$y;
            h_r$5$d = h$5$y;
            h_r$6$d = h$6$y;
            h_r$7$d = h$7$y;
            b_r$d = b;
            c_r$0$d = round$0$y;
            c_r$1$d = round$1$y;
            c_r$2$d = round$2$y;
            c_r$3$d = round$3$y;
        end
        c = (((c_r$3$q) & 32'hffffffff) << 32'h18) | (((c_r$2$q) & 32'hffffffff) << 32'h10) | (((c_r$1$q) & 32'hffffffff) << 32'h8) | ((c_r$0$q) & 32'hffffffff);
    end
    
endmodule // texture_filter$level$0


module texture_filter$level$0$b_r(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$b_r


module texture_filter$level$0$c_r$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$c_r$0


module texture_filter$level$0$c_r$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$c_r$1


module texture_filter$level$0$c_r$2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$c_r$2


module texture_filter$level$0$c_r$3(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$c_r$3


module texture_filter$level$0$h$0(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$h$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$0$h$0


module texture_filter$level$0$h$0$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$h$0$mul


module texture_filter$level$0$h$1(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$h$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$0$h$1


module texture_filter$level$0$h$1$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$h$1$mul


module texture_filter$level$0$h$2(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$h$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$0$h$2


module texture_filter$level$0$h$2$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$h$2$mul


module texture_filter$level$0$h$3(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$h$3$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$0$h$3


module texture_filter$level$0$h$3$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$h$3$mul


module texture_filter$level$0$h$4(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$h$4$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$0$h$4


module texture_filter$level$0$h$4$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$h$4$mul


module texture_filter$level$0$h$5(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$h$5$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$0$h$5


module texture_filter$level$0$h$5$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$h$5$mul


module texture_filter$level$0$h$6(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$h$6$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$0$h$6


module texture_filter$level$0$h$6$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$h$6$mul


module texture_filter$level$0$h$7(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$h$7$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$0$h$7


module texture_filter$level$0$h$7$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$h$7$mul


module texture_filter$level$0$h_r$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$h_r$0


module texture_filter$level$0$h_r$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$h_r$1


module texture_filter$level$0$h_r$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$h_r$2


module texture_filter$level$0$h_r$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$h_r$3


module texture_filter$level$0$h_r$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$h_r$4


module texture_filter$level$0$h_r$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$h_r$5


module texture_filter$level$0$h_r$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$h_r$6


module texture_filter$level$0$h_r$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$0$h_r$7


module texture_filter$level$0$round$0(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$level$0$round$0


module texture_filter$level$0$round$1(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$level$0$round$1


module texture_filter$level$0$round$2(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$level$0$round$2


module texture_filter$level$0$round$3(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$level$0$round$3


module texture_filter$level$0$v$0(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$v$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_filter$level$0$v$0


module texture_filter$level$0$v$0$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$v$0$mul


module texture_filter$level$0$v$1(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$v$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_filter$level$0$v$1


module texture_filter$level$0$v$1$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$v$1$mul


module texture_filter$level$0$v$2(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$v$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_filter$level$0$v$2


module texture_filter$level$0$v$2$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$v$2$mul


module texture_filter$level$0$v$3(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_filter$level$0$v$3$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_filter$level$0$v$3


module texture_filter$level$0$v$3$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$0$v$3$mul


module texture_filter$level$1(clock,en,t0,t1,t2,t3,a,b,c);
    
    // Module arguments
    input wire  clock;
    input wire  en;
    input wire  [31:0] t0;
    input wire  [31:0] t1;
    input wire  [31:0] t2;
    input wire  [31:0] t3;
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [31:0] c;
    
    // Stub signals
    reg  [7:0] h$0$x0;
    reg  [7:0] h$0$x1;
    reg  [8:0] h$0$w;
    wire  [15:0] h$0$y;
    reg  [7:0] h$1$x0;
    reg  [7:0] h$1$x1;
    reg  [8:0] h$1$w;
    wire  [15:0] h$1$y;
    reg  [7:0] h$2$x0;
    reg  [7:0] h$2$x1;
    reg  [8:0] h$2$w;
    wire  [15:0] h$2$y;
    reg  [7:0] h$3$x0;
    reg  [7:0] h$3$x1;
    reg  [8:0] h$3$w;
    wire  [15:0] h$3$y;
    reg  [7:0] h$4$x0;
    reg  [7:0] h$4$x1;
    reg  [8:0] h$4$w;
    wire  [15:0] h$4$y;
    reg  [7:0] h$5$x0;
    reg  [7:0] h$5$x1;
    reg  [8:0] h$5$w;
    wire  [15:0] h$5$y;
    reg  [7:0] h$6$x0;
    reg  [7:0] h$6$x1;
    reg  [8:0] h$6$w;
    wire  [15:0] h$6$y;
    reg  [7:0] h$7$x0;
    reg  [7:0] h$7$x1;
    reg  [8:0] h$7$w;
    wire  [15:0] h$7$y;
    reg  [15:0] h_r$0$d;
    wire  [15:0] h_r$0$q;
    reg  h_r$0$clock;
    reg  [15:0] h_r$1$d;
    wire  [15:0] h_r$1$q;
    reg  h_r$1$clock;
    reg  [15:0] h_r$2$d;
    wire  [15:0] h_r$2$q;
    reg  h_r$2$clock;
    reg  [15:0] h_r$3$d;
    wire  [15:0] h_r$3$q;
    reg  h_r$3$clock;
    reg  [15:0] h_r$4$d;
    wire  [15:0] h_r$4$q;
    reg  h_r$4$clock;
    reg  [15:0] h_r$5$d;
    wire  [15:0] h_r$5$q;
    reg  h_r$5$clock;
    reg  [15:0] h_r$6$d;
    wire  [15:0] h_r$6$q;
    reg  h_r$6$clock;
    reg  [15:0] h_r$7$d;
    wire  [15:0] h_r$7$q;
    reg  h_r$7$clock;
    reg  [8:0] b_r$d;
    wire  [8:0] b_r$q;
    reg  b_r$clock;
    reg  [15:0] v$0$x0;
    reg  [15:0] v$0$x1;
    reg  [8:0] v$0$w;
    wire  [23:0] v$0$y;
    reg  [15:0] v$1$x0;
    reg  [15:0] v$1$x1;
    reg  [8:0] v$1$w;
    wire  [23:0] v$1$y;
    reg  [15:0] v$2$x0;
    reg  [15:0] v$2$x1;
    reg  [8:0] v$2$w;
    wire  [23:0] v$2$y;
    reg  [15:0] v$3$x0;
    reg  [15:0] v$3$x1;
    reg  [8:0] v$3$w;
    wire  [23:0] v$3$y;
    reg  [23:0] round$0$x;
    wire  [7:0] round$0$y;
    reg  [23:0] round$1$x;
    wire  [7:0] round$1$y;
    reg  [23:0] round$2$x;
    wire  [7:0] round$2$y;
    reg  [23:0] round$3$x;
    wire  [7:0] round$3$y;
    reg  [7:0] c_r$0$d;
    wire  [7:0] c_r$0$q;
    reg  c_r$0$clock;
    reg  [7:0] c_r$1$d;
    wire  [7:0] c_r$1$q;
    reg  c_r$1$clock;
    reg  [7:0] c_r$2$d;
    wire  [7:0] c_r$2$q;
    reg  c_r$2$clock;
    reg  [7:0] c_r$3$d;
    wire  [7:0] c_r$3$q;
    reg  c_r$3$clock;
    
    // Sub module instances
    texture_filter$level$1$h$0 h$0(
        .x0(h$0$x0),
        .x1(h$0$x1),
        .w(h$0$w),
        .y(h$0$y)
    );
    texture_filter$level$1$h$1 h$1(
        .x0(h$1$x0),
        .x1(h$1$x1),
        .w(h$1$w),
        .y(h$1$y)
    );
    texture_filter$level$1$h$2 h$2(
        .x0(h$2$x0),
        .x1(h$2$x1),
        .w(h$2$w),
        .y(h$2$y)
    );
    texture_filter$level$1$h$3 h$3(
        .x0(h$3$x0),
        .x1(h$3$x1),
        .w(h$3$w),
        .y(h$3$y)
    );
    texture_filter$level$1$h$4 h$4(
        .x0(h$4$x0),
        .x1(h$4$x1),
        .w(h$4$w),
        .y(h$4$y)
    );
    texture_filter$level$1$h$5 h$5(
        .x0(h$5$x0),
        .x1(h$5$x1),
        .w(h$5$w),
        .y(h$5$y)
    );
    texture_filter$level$1$h$6 h$6(
        .x0(h$6$x0),
        .x1(h$6$x1),
        .w(h$6$w),
        .y(h$6$y)
    );
    texture_filter$level$1$h$7 h$7(
        .x0(h$7$x0),
        .x1(h$7$x1),
        .w(h$7$w),
        .y(h$7$y)
    );
    texture_filter$level$1$h_r$0 h_r$0(
        .d(h_r$0$d),
        .q(h_r$0$q),
        .clock(h_r$0$clock)
    );
    texture_filter$level$1$h_r$1 h_r$1(
        .d(h_r$1$d),
        .q(h_r$1$q),
        .clock(h_r$1$clock)
    );
    texture_filter$level$1$h_r$2 h_r$2(
        .d(h_r$2$d),
        .q(h_r$2$q),
        .clock(h_r$2$clock)
    );
    texture_filter$level$1$h_r$3 h_r$3(
        .d(h_r$3$d),
        .q(h_r$3$q),
        .clock(h_r$3$clock)
    );
    texture_filter$level$1$h_r$4 h_r$4(
        .d(h_r$4$d),
        .q(h_r$4$q),
        .clock(h_r$4$clock)
    );
    texture_filter$level$1$h_r$5 h_r$5(
        .d(h_r$5$d),
        .q(h_r$5$q),
        .clock(h_r$5$clock)
    );
    texture_filter$level$1$h_r$6 h_r$6(
        .d(h_r$6$d),
        .q(h_r$6$q),
        .clock(h_r$6$clock)
    );
    texture_filter$level$1$h_r$7 h_r$7(
        .d(h_r$7$d),
        .q(h_r$7$q),
        .clock(h_r$7$clock)
    );
    texture_filter$level$1$b_r b_r(
        .d(b_r$d),
        .q(b_r$q),
        .clock(b_r$clock)
    );
    texture_filter$level$1$v$0 v$0(
        .x0(v$0$x0),
        .x1(v$0$x1),
        .w(v$0$w),
        .y(v$0$y)
    );
    texture_filter$level$1$v$1 v$1(
        .x0(v$1$x0),
        .x1(v$1$x1),
        .w(v$1$w),
        .y(v$1$y)
    );
    texture_filter$level$1$v$2 v$2(
        .x0(v$2$x0),
        .x1(v$2$x1),
        .w(v$2$w),
        .y(v$2$y)
    );
    texture_filter$level$1$v$3 v$3(
        .x0(v$3$x0),
        .x1(v$3$x1),
        .w(v$3$w),
        .y(v$3$y)
    );
    texture_filter$level$1$round$0 round$0(
        .x(round$0$x),
        .y(round$0$y)
    );
    texture_filter$level$1$round$1 round$1(
        .x(round$1$x),
        .y(round$1$y)
    );
    texture_filter$level$1$round$2 round$2(
        .x(round$2$x),
        .y(round$2$y)
    );
    texture_filter$level$1$round$3 round$3(
        .x(round$3$x),
        .y(round$3$y)
    );
    texture_filter$level$1$c_r$0 c_r$0(
        .d(c_r$0$d),
        .q(c_r$0$q),
        .clock(c_r$0$clock)
    );
    texture_filter$level$1$c_r$1 c_r$1(
        .d(c_r$1$d),
        .q(c_r$1$q),
        .clock(c_r$1$clock)
    );
    texture_filter$level$1$c_r$2 c_r$2(
        .d(c_r$2$d),
        .q(c_r$2$q),
        .clock(c_r$2$clock)
    );
    texture_filter$level$1$c_r$3 c_r$3(
        .d(c_r$3$d),
        .q(c_r$3$q),
        .clock(c_r$3$clock)
    );
    
    // Update code
    always @(*) begin
        b_r$clock = clock;
        b_r$d = b_r$q;
        h_r$0$clock = clock;
        h_r$0$d = h_r$0$q;
        h_r$1$clock = clock;
        h_r$1$d = h_r$1$q;
        h_r$2$clock = clock;
        h_r$2$d = h_r$2$q;
        h_r$3$clock = clock;
        h_r$3$d = h_r$3$q;
        h_r$4$clock = clock;
        h_r$4$d = h_r$4$q;
        h_r$5$clock = clock;
        h_r$5$d = h_r$5$q;
        h_r$6$clock = clock;
        h_r$6$d = h_r$6$q;
        h_r$7$clock = clock;
        h_r$7$d = h_r$7$q;
        c_r$0$clock = clock;
        c_r$0$d = c_r$0$q;
        c_r$1$clock = clock;
        c_r$1$d = c_r$1$q;
        c_r$2$clock = clock;
        c_r$2$d = c_r$2$q;
        c_r$3$clock = clock;
        c_r$3$d = c_r$3$q;
        h$0$x0 = t0[(0 * 32'h8)+:(8)];
        h$0$x1 = t1[(0 * 32'h8)+:(8)];
        h$0$w = a;
        h$4$x0 = t2[(0 * 32'h8)+:(8)];
        h$4$x1 = t3[(0 * 32'h8)+:(8)];
        h$4$w = a;
        v$0$x0 = h_r$0$q;
        v$0$x1 = h_r$4$q;
        v$0$w = b_r$q;
        round$0$x = v$0$y;
        h$1$x0 = t0[(1 * 32'h8)+:(8)];
        h$1$x1 = t1[(1 * 32'h8)+:(8)];
        h$1$w = a;
        h$5$x0 = t2[(1 * 32'h8)+:(8)];
        h$5$x1 = t3[(1 * 32'h8)+:(8)];
        h$5$w = a;
        v$1$x0 = h_r$1$q;
        v$1$x1 = h_r$5$q;
        v$1$w = b_r$q;
        round$1$x = v$1$y;
        h$2$x0 = t0[(2 * 32'h8)+:(8)];
        h$2$x1 = t1[(2 * 32'h8)+:(8)];
        h$2$w = a;
        h$6$x0 = t2[(2 * 32'h8)+:(8)];
        h$6$x1 = t3[(2 * 32'h8)+:(8)];
        h$6$w = a;
        v$2$x0 = h_r$2$q;
        v$2$x1 = h_r$6$q;
        v$2$w = b_r$q;
        round$2$x = v$2$y;
        h$3$x0 = t0[(3 * 32'h8)+:(8)];
        h$3$x1 = t1[(3 * 32'h8)+:(8)];
        h$3$w = a;
        h$7$x0 = t2[(3 * 32'h8)+:(8)];
        h$7$x1 = t3[(3 * 32'h8)+:(8)];
        h$7$w = a;
        v$3$x0 = h_r$3$q;
        v$3$x1 = h_r$7$q;
        v$3$w = b_r$q;
        round$3$x = v$3$y;
        if (en) begin
            h_r$0$d = h$0$y;
            h_r$1$d = h$1$y;
            h_r$2$d = h$2$y;
            h_r$3$d = h$3$y;
            h_r$4$d = h$4$y;
            h_r$5$d = h$5$y;
            h_r$6$d = h$6$y;
            h_r$7$d = h$7$y;
            b_r$d = b;
            c_r$0$d = round$0$y;
            c_r$1$d = round$1$y;
            c_r$2$d = round$2$y;
            c_r$3$d = round$3$y;
        end
        c = (((c_r$3$q) & 32'hffffffff) << 32'h18) | (((c_r$2$q) & 32'hffffffff) << 32'h10) | (((c_r$1$q) & 32'hffffffff) << 32'h8) | ((c_r$0$q) & 32'hffffffff);
    end
    
endmodule // texture_filter$level$1


module texture_filter$level$1$b_r(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$b_r


module texture_filter$level$1$c_r$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$c_r$0


module texture_filter$level$1$c_r$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$c_r$1


module texture_filter$level$1$c_r$2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$c_r$2


module texture_filter$level$1$c_r$3(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$c_r$3


module texture_filter$level$1$h$0(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$h$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$1$h$0


module texture_filter$level$1$h$0$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$h$0$mul


module texture_filter$level$1$h$1(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$h$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$1$h$1


module texture_filter$level$1$h$1$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$h$1$mul


module texture_filter$level$1$h$2(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$h$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$1$h$2


module texture_filter$level$1$h$2$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$h$2$mul


module texture_filter$level$1$h$3(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$h$3$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$1$h$3


module texture_filter$level$1$h$3$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$h$3$mul


module texture_filter$level$1$h$4(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$h$4$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$1$h$4


module texture_filter$level$1$h$4$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$h$4$mul


module texture_filter$level$1$h$5(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$h$5$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$1$h$5


module texture_filter$level$1$h$5$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$h$5$mul


module texture_filter$level$1$h$6(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$h$6$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$1$h$6


module texture_filter$level$1$h$6$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$h$6$mul


module texture_filter$level$1$h$7(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [8:0] w;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [9:0] mul$b;
    wire  [16:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$h$7$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 17'h1ffff) << s) + mul$p) & 16'hffff);
    end
    
endmodule // texture_filter$level$1$h$7


module texture_filter$level$1$h$7$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [9:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$h$7$mul


module texture_filter$level$1$h_r$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$h_r$0


module texture_filter$level$1$h_r$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$h_r$1


module texture_filter$level$1$h_r$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$h_r$2


module texture_filter$level$1$h_r$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$h_r$3


module texture_filter$level$1$h_r$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$h_r$4


module texture_filter$level$1$h_r$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$h_r$5


module texture_filter$level$1$h_r$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$h_r$6


module texture_filter$level$1$h_r$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$level$1$h_r$7


module texture_filter$level$1$round$0(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$level$1$round$0


module texture_filter$level$1$round$1(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$level$1$round$1


module texture_filter$level$1$round$2(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$level$1$round$2


module texture_filter$level$1$round$3(x,y);
    
    // Module arguments
    input wire  [23:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 24'h8000;
    localparam  shift = 8'h10;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$level$1$round$3


module texture_filter$level$1$v$0(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$v$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_filter$level$1$v$0


module texture_filter$level$1$v$0$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$v$0$mul


module texture_filter$level$1$v$1(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$v$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_filter$level$1$v$1


module texture_filter$level$1$v$1$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$v$1$mul


module texture_filter$level$1$v$2(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$v$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_filter$level$1$v$2


module texture_filter$level$1$v$2$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$v$2$mul


module texture_filter$level$1$v$3(x0,x1,w,y);
    
    // Module arguments
    input wire  [15:0] x0;
    input wire  [15:0] x1;
    input wire  [8:0] w;
    output reg  [23:0] y;
    
    // Constant declarations
    localparam  s = 8'h8;
    
    // Stub signals
    reg  [16:0] mul$a;
    reg  [9:0] mul$b;
    wire  [24:0] mul$p;
    
    // Sub module instances
    texture_filter$level$1$v$3$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 17'h1ffff) - ((x0) & 17'h1ffff);
        mul$b = ((w) & 10'h3ff);
        y = (((((x0) & 25'h1ffffff) << s) + mul$p) & 24'hffffff);
    end
    
endmodule // texture_filter$level$1$v$3


module texture_filter$level$1$v$3$mul(a,b,p);
    
    // Module arguments
    input wire  [16:0] a;
    input wire  [9:0] b;
    output reg  [24:0] p;
    
    // Update code (custom)
    // p = low 25 bits of a * b, both signed: a signed 25-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$level$1$v$3$mul


module texture_filter$mix$0(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [6:0] w;
    output reg  [13:0] y;
    
    // Constant declarations
    localparam  s = 8'h6;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [7:0] mul$b;
    wire  [14:0] mul$p;
    
    // Sub module instances
    texture_filter$mix$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 8'hff);
        y = (((((x0) & 15'h7fff) << s) + mul$p) & 14'h3fff);
    end
    
endmodule // texture_filter$mix$0


module texture_filter$mix$0$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [7:0] b;
    output reg  [14:0] p;
    
    // Update code (custom)
    // p = low 15 bits of a * b, both signed: a signed 15-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$mix$0$mul


module texture_filter$mix$1(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [6:0] w;
    output reg  [13:0] y;
    
    // Constant declarations
    localparam  s = 8'h6;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [7:0] mul$b;
    wire  [14:0] mul$p;
    
    // Sub module instances
    texture_filter$mix$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 8'hff);
        y = (((((x0) & 15'h7fff) << s) + mul$p) & 14'h3fff);
    end
    
endmodule // texture_filter$mix$1


module texture_filter$mix$1$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [7:0] b;
    output reg  [14:0] p;
    
    // Update code (custom)
    // p = low 15 bits of a * b, both signed: a signed 15-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$mix$1$mul


module texture_filter$mix$2(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [6:0] w;
    output reg  [13:0] y;
    
    // Constant declarations
    localparam  s = 8'h6;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [7:0] mul$b;
    wire  [14:0] mul$p;
    
    // Sub module instances
    texture_filter$mix$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 8'hff);
        y = (((((x0) & 15'h7fff) << s) + mul$p) & 14'h3fff);
    end
    
endmodule // texture_filter$mix$2


module texture_filter$mix$2$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [7:0] b;
    output reg  [14:0] p;
    
    // Update code (custom)
    // p = low 15 bits of a * b, both signed: a signed 15-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$mix$2$mul


module texture_filter$mix$3(x0,x1,w,y);
    
    // Module arguments
    input wire  [7:0] x0;
    input wire  [7:0] x1;
    input wire  [6:0] w;
    output reg  [13:0] y;
    
    // Constant declarations
    localparam  s = 8'h6;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [7:0] mul$b;
    wire  [14:0] mul$p;
    
    // Sub module instances
    texture_filter$mix$3$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        mul$a = ((x1) & 9'h1ff) - ((x0) & 9'h1ff);
        mul$b = ((w) & 8'hff);
        y = (((((x0) & 15'h7fff) << s) + mul$p) & 14'h3fff);
    end
    
endmodule // texture_filter$mix$3


module texture_filter$mix$3$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [7:0] b;
    output reg  [14:0] p;
    
    // Update code (custom)
    // p = low 15 bits of a * b, both signed: a signed 15-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // texture_filter$mix$3$mul


module texture_filter$mix_round$0(x,y);
    
    // Module arguments
    input wire  [13:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 14'b100000;
    localparam  shift = 8'h6;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$mix_round$0


module texture_filter$mix_round$1(x,y);
    
    // Module arguments
    input wire  [13:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 14'b100000;
    localparam  shift = 8'h6;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$mix_round$1


module texture_filter$mix_round$2(x,y);
    
    // Module arguments
    input wire  [13:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 14'b100000;
    localparam  shift = 8'h6;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$mix_round$2


module texture_filter$mix_round$3(x,y);
    
    // Module arguments
    input wire  [13:0] x;
    output reg  [7:0] y;
    
    // Constant declarations
    localparam  half = 14'b100000;
    localparam  shift = 8'h6;
    
    // Update code
    always @(*) begin
        y = (((x + half) >> shift) & 8'hff);
    end
    
endmodule // texture_filter$mix_round$3


module texture_filter$s1_a$0(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_a$0


module texture_filter$s1_a$1(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_a$1


module texture_filter$s1_b$0(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_b$0


module texture_filter$s1_b$1(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_b$1


module texture_filter$s1_cf(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_cf


module texture_filter$s1_env(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_env


module texture_filter$s1_frac(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_frac


module texture_filter$s1_texel$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_texel$0


module texture_filter$s1_texel$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_texel$1


module texture_filter$s1_texel$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_texel$2


module texture_filter$s1_texel$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_texel$3


module texture_filter$s1_texel$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_texel$4


module texture_filter$s1_texel$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_texel$5


module texture_filter$s1_texel$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_texel$6


module texture_filter$s1_texel$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_texel$7


module texture_filter$s1_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_two


module texture_filter$s1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s1_valid


module texture_filter$s2_cf(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s2_cf


module texture_filter$s2_env(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s2_env


module texture_filter$s2_frac(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s2_frac


module texture_filter$s2_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s2_two


module texture_filter$s2_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s2_valid


module texture_filter$s3_cf(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s3_cf


module texture_filter$s3_env(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s3_env


module texture_filter$s3_frac(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s3_frac


module texture_filter$s3_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s3_two


module texture_filter$s3_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s3_valid


module texture_filter$s4_cf(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s4_cf


module texture_filter$s4_cs$0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s4_cs$0


module texture_filter$s4_cs$1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s4_cs$1


module texture_filter$s4_cs$2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s4_cs$2


module texture_filter$s4_cs$3(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s4_cs$3


module texture_filter$s4_env(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s4_env


module texture_filter$s4_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s4_valid


module texture_filter$s5_rgba(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s5_rgba


module texture_filter$s5_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_filter$s5_valid


module texture_filter$weight$0(alpha,gaussian,w);
    
    // Module arguments
    input wire  [7:0] alpha;
    input wire  gaussian;
    output reg  [8:0] w;
    
    // Constant declarations
    localparam  down = 8'h0;
    localparam  up = 8'h0;
    
    // Stub signals
    reg  [7:0] rom$address;
    wire  [8:0] rom$data;
    
    // Sub module instances
    texture_filter$weight$0$rom rom(
        .address(rom$address),
        .data(rom$data)
    );
    
    // Update code
    always @(*) begin
        rom$address = alpha;
        w = ((alpha >> down) & 9'h1ff) << up;
        if (gaussian) begin
            w = rom$data;
        end
    end
    
endmodule // texture_filter$weight$0


module texture_filter$weight$0$rom(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [8:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 9'b0;
      8'h1: data = 9'b0;
      8'h2: data = 9'b0;
      8'h3: data = 9'b0;
      8'h4: data = 9'b0;
      8'h5: data = 9'b0;
      8'h6: data = 9'b0;
      8'h7: data = 9'b1;
      8'h8: data = 9'b1;
      8'h9: data = 9'b1;
      8'ha: data = 9'b1;
      8'hb: data = 9'b1;
      8'hc: data = 9'b10;
      8'hd: data = 9'b10;
      8'he: data = 9'b10;
      8'hf: data = 9'b11;
      8'h10: data = 9'b11;
      8'h11: data = 9'b11;
      8'h12: data = 9'b100;
      8'h13: data = 9'b100;
      8'h14: data = 9'b100;
      8'h15: data = 9'b101;
      8'h16: data = 9'b101;
      8'h17: data = 9'b110;
      8'h18: data = 9'b110;
      8'h19: data = 9'b111;
      8'h1a: data = 9'b111;
      8'h1b: data = 9'b1000;
      8'h1c: data = 9'b1001;
      8'h1d: data = 9'b1001;
      8'h1e: data = 9'b1010;
      8'h1f: data = 9'b1010;
      8'h20: data = 9'b1011;
      8'h21: data = 9'b1100;
      8'h22: data = 9'b1100;
      8'h23: data = 9'b1101;
      8'h24: data = 9'b1110;
      8'h25: data = 9'b1110;
      8'h26: data = 9'b1111;
      8'h27: data = 9'b10000;
      8'h28: data = 9'b10001;
      8'h29: data = 9'b10010;
      8'h2a: data = 9'b10010;
      8'h2b: data = 9'b10011;
      8'h2c: data = 9'b10100;
      8'h2d: data = 9'b10101;
      8'h2e: data = 9'b10110;
      8'h2f: data = 9'b10111;
      8'h30: data = 9'b11000;
      8'h31: data = 9'b11001;
      8'h32: data = 9'b11001;
      8'h33: data = 9'b11010;
      8'h34: data = 9'b11011;
      8'h35: data = 9'b11100;
      8'h36: data = 9'b11101;
      8'h37: data = 9'b11110;
      8'h38: data = 9'b11111;
      8'h39: data = 9'b100000;
      8'h3a: data = 9'b100001;
      8'h3b: data = 9'b100011;
      8'h3c: data = 9'b100100;
      8'h3d: data = 9'b100101;
      8'h3e: data = 9'b100110;
      8'h3f: data = 9'b100111;
      8'h40: data = 9'b101000;
      8'h41: data = 9'b101001;
      8'h42: data = 9'b101010;
      8'h43: data = 9'b101011;
      8'h44: data = 9'b101101;
      8'h45: data = 9'b101110;
      8'h46: data = 9'b101111;
      8'h47: data = 9'b110000;
      8'h48: data = 9'b110001;
      8'h49: data = 9'b110011;
      8'h4a: data = 9'b110100;
      8'h4b: data = 9'b110101;
      8'h4c: data = 9'b110110;
      8'h4d: data = 9'b111000;
      8'h4e: data = 9'b111001;
      8'h4f: data = 9'b111010;
      8'h50: data = 9'b111011;
      8'h51: data = 9'b111101;
      8'h52: data = 9'b111110;
      8'h53: data = 9'b111111;
      8'h54: data = 9'b1000001;
      8'h55: data = 9'b1000010;
      8'h56: data = 9'b1000011;
      8'h57: data = 9'b1000101;
      8'h58: data = 9'b1000110;
      8'h59: data = 9'b1000111;
      8'h5a: data = 9'b1001001;
      8'h5b: data = 9'b1001010;
      8'h5c: data = 9'b1001011;
      8'h5d: data = 9'b1001101;
      8'h5e: data = 9'b1001110;
      8'h5f: data = 9'b1010000;
      8'h60: data = 9'b1010001;
      8'h61: data = 9'b1010010;
      8'h62: data = 9'b1010100;
      8'h63: data = 9'b1010101;
      8'h64: data = 9'b1010111;
      8'h65: data = 9'b1011000;
      8'h66: data = 9'b1011010;
      8'h67: data = 9'b1011011;
      8'h68: data = 9'b1011100;
      8'h69: data = 9'b1011110;
      8'h6a: data = 9'b1011111;
      8'h6b: data = 9'b1100001;
      8'h6c: data = 9'b1100010;
      8'h6d: data = 9'b1100100;
      8'h6e: data = 9'b1100101;
      8'h6f: data = 9'b1100111;
      8'h70: data = 9'b1101000;
      8'h71: data = 9'b1101010;
      8'h72: data = 9'b1101011;
      8'h73: data = 9'b1101101;
      8'h74: data = 9'b1101110;
      8'h75: data = 9'b1110000;
      8'h76: data = 9'b1110001;
      8'h77: data = 9'b1110011;
      8'h78: data = 9'b1110100;
      8'h79: data = 9'b1110110;
      8'h7a: data = 9'b1110111;
      8'h7b: data = 9'b1111001;
      8'h7c: data = 9'b1111010;
      8'h7d: data = 9'b1111100;
      8'h7e: data = 9'b1111101;
      8'h7f: data = 9'b1111111;
      8'h80: data = 9'b10000000;
      8'h81: data = 9'b10000001;
      8'h82: data = 9'b10000011;
      8'h83: data = 9'b10000100;
      8'h84: data = 9'b10000110;
      8'h85: data = 9'b10000111;
      8'h86: data = 9'b10001001;
      8'h87: data = 9'b10001010;
      8'h88: data = 9'b10001100;
      8'h89: data = 9'b10001101;
      8'h8a: data = 9'b10001111;
      8'h8b: data = 9'b10010000;
      8'h8c: data = 9'b10010010;
      8'h8d: data = 9'b10010011;
      8'h8e: data = 9'b10010101;
      8'h8f: data = 9'b10010110;
      8'h90: data = 9'b10011000;
      8'h91: data = 9'b10011001;
      8'h92: data = 9'b10011011;
      8'h93: data = 9'b10011100;
      8'h94: data = 9'b10011110;
      8'h95: data = 9'b10011111;
      8'h96: data = 9'b10100001;
      8'h97: data = 9'b10100010;
      8'h98: data = 9'b10100100;
      8'h99: data = 9'b10100101;
      8'h9a: data = 9'b10100110;
      8'h9b: data = 9'b10101000;
      8'h9c: data = 9'b10101001;
      8'h9d: data = 9'b10101011;
      8'h9e: data = 9'b10101100;
      8'h9f: data = 9'b10101110;
      8'ha0: data = 9'b10101111;
      8'ha1: data = 9'b10110000;
      8'ha2: data = 9'b10110010;
      8'ha3: data = 9'b10110011;
      8'ha4: data = 9'b10110101;
      8'ha5: data = 9'b10110110;
      8'ha6: data = 9'b10110111;
      8'ha7: data = 9'b10111001;
      8'ha8: data = 9'b10111010;
      8'ha9: data = 9'b10111011;
      8'haa: data = 9'b10111101;
      8'hab: data = 9'b10111110;
      8'hac: data = 9'b10111111;
      8'had: data = 9'b11000001;
      8'hae: data = 9'b11000010;
      8'haf: data = 9'b11000011;
      8'hb0: data = 9'b11000101;
      8'hb1: data = 9'b11000110;
      8'hb2: data = 9'b11000111;
      8'hb3: data = 9'b11001000;
      8'hb4: data = 9'b11001010;
      8'hb5: data = 9'b11001011;
      8'hb6: data = 9'b11001100;
      8'hb7: data = 9'b11001101;
      8'hb8: data = 9'b11001111;
      8'hb9: data = 9'b11010000;
      8'hba: data = 9'b11010001;
      8'hbb: data = 9'b11010010;
      8'hbc: data = 9'b11010011;
      8'hbd: data = 9'b11010101;
      8'hbe: data = 9'b11010110;
      8'hbf: data = 9'b11010111;
      8'hc0: data = 9'b11011000;
      8'hc1: data = 9'b11011001;
      8'hc2: data = 9'b11011010;
      8'hc3: data = 9'b11011011;
      8'hc4: data = 9'b11011100;
      8'hc5: data = 9'b11011101;
      8'hc6: data = 9'b11011111;
      8'hc7: data = 9'b11100000;
      8'hc8: data = 9'b11100001;
      8'hc9: data = 9'b11100010;
      8'hca: data = 9'b11100011;
      8'hcb: data = 9'b11100100;
      8'hcc: data = 9'b11100101;
      8'hcd: data = 9'b11100110;
      8'hce: data = 9'b11100111;
      8'hcf: data = 9'b11100111;
      8'hd0: data = 9'b11101000;
      8'hd1: data = 9'b11101001;
      8'hd2: data = 9'b11101010;
      8'hd3: data = 9'b11101011;
      8'hd4: data = 9'b11101100;
      8'hd5: data = 9'b11101101;
      8'hd6: data = 9'b11101110;
      8'hd7: data = 9'b11101110;
      8'hd8: data = 9'b11101111;
      8'hd9: data = 9'b11110000;
      8'hda: data = 9'b11110001;
      8'hdb: data = 9'b11110010;
      8'hdc: data = 9'b11110010;
      8'hdd: data = 9'b11110011;
      8'hde: data = 9'b11110100;
      8'hdf: data = 9'b11110100;
      8'he0: data = 9'b11110101;
      8'he1: data = 9'b11110110;
      8'he2: data = 9'b11110110;
      8'he3: data = 9'b11110111;
      8'he4: data = 9'b11110111;
      8'he5: data = 9'b11111000;
      8'he6: data = 9'b11111001;
      8'he7: data = 9'b11111001;
      8'he8: data = 9'b11111010;
      8'he9: data = 9'b11111010;
      8'hea: data = 9'b11111011;
      8'heb: data = 9'b11111011;
      8'hec: data = 9'b11111100;
      8'hed: data = 9'b11111100;
      8'hee: data = 9'b11111100;
      8'hef: data = 9'b11111101;
      8'hf0: data = 9'b11111101;
      8'hf1: data = 9'b11111101;
      8'hf2: data = 9'b11111110;
      8'hf3: data = 9'b11111110;
      8'hf4: data = 9'b11111110;
      8'hf5: data = 9'b11111111;
      8'hf6: data = 9'b11111111;
      8'hf7: data = 9'b11111111;
      8'hf8: data = 9'b11111111;
      8'hf9: data = 9'b11111111;
      8'hfa: data = 9'b100000000;
      8'hfb: data = 9'b100000000;
      8'hfc: data = 9'b100000000;
      8'hfd: data = 9'b100000000;
      8'hfe: data = 9'b100000000;
      8'hff: data = 9'b100000000;
      default: data = 9'b0;
    endcase
            
endmodule // texture_filter$weight$0$rom


module texture_filter$weight$1(alpha,gaussian,w);
    
    // Module arguments
    input wire  [7:0] alpha;
    input wire  gaussian;
    output reg  [8:0] w;
    
    // Constant declarations
    localparam  down = 8'h0;
    localparam  up = 8'h0;
    
    // Stub signals
    reg  [7:0] rom$address;
    wire  [8:0] rom$data;
    
    // Sub module instances
    texture_filter$weight$1$rom rom(
        .address(rom$address),
        .data(rom$data)
    );
    
    // Update code
    always @(*) begin
        rom$address = alpha;
        w = ((alpha >> down) & 9'h1ff) << up;
        if (gaussian) begin
            w = rom$data;
        end
    end
    
endmodule // texture_filter$weight$1


module texture_filter$weight$1$rom(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [8:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 9'b0;
      8'h1: data = 9'b0;
      8'h2: data = 9'b0;
      8'h3: data = 9'b0;
      8'h4: data = 9'b0;
      8'h5: data = 9'b0;
      8'h6: data = 9'b0;
      8'h7: data = 9'b1;
      8'h8: data = 9'b1;
      8'h9: data = 9'b1;
      8'ha: data = 9'b1;
      8'hb: data = 9'b1;
      8'hc: data = 9'b10;
      8'hd: data = 9'b10;
      8'he: data = 9'b10;
      8'hf: data = 9'b11;
      8'h10: data = 9'b11;
      8'h11: data = 9'b11;
      8'h12: data = 9'b100;
      8'h13: data = 9'b100;
      8'h14: data = 9'b100;
      8'h15: data = 9'b101;
      8'h16: data = 9'b101;
      8'h17: data = 9'b110;
      8'h18: data = 9'b110;
      8'h19: data = 9'b111;
      8'h1a: data = 9'b111;
      8'h1b: data = 9'b1000;
      8'h1c: data = 9'b1001;
      8'h1d: data = 9'b1001;
      8'h1e: data = 9'b1010;
      8'h1f: data = 9'b1010;
      8'h20: data = 9'b1011;
      8'h21: data = 9'b1100;
      8'h22: data = 9'b1100;
      8'h23: data = 9'b1101;
      8'h24: data = 9'b1110;
      8'h25: data = 9'b1110;
      8'h26: data = 9'b1111;
      8'h27: data = 9'b10000;
      8'h28: data = 9'b10001;
      8'h29: data = 9'b10010;
      8'h2a: data = 9'b10010;
      8'h2b: data = 9'b10011;
      8'h2c: data = 9'b10100;
      8'h2d: data = 9'b10101;
      8'h2e: data = 9'b10110;
      8'h2f: data = 9'b10111;
      8'h30: data = 9'b11000;
      8'h31: data = 9'b11001;
      8'h32: data = 9'b11001;
      8'h33: data = 9'b11010;
      8'h34: data = 9'b11011;
      8'h35: data = 9'b11100;
      8'h36: data = 9'b11101;
      8'h37: data = 9'b11110;
      8'h38: data = 9'b11111;
      8'h39: data = 9'b100000;
      8'h3a: data = 9'b100001;
      8'h3b: data = 9'b100011;
      8'h3c: data = 9'b100100;
      8'h3d: data = 9'b100101;
      8'h3e: data = 9'b100110;
      8'h3f: data = 9'b100111;
      8'h40: data = 9'b101000;
      8'h41: data = 9'b101001;
      8'h42: data = 9'b101010;
      8'h43: data = 9'b101011;
      8'h44: data = 9'b101101;
      8'h45: data = 9'b101110;
      8'h46: data = 9'b101111;
      8'h47: data = 9'b110000;
      8'h48: data = 9'b110001;
      8'h49: data = 9'b110011;
      8'h4a: data = 9'b110100;
      8'h4b: data = 9'b110101;
      8'h4c: data = 9'b110110;
      8'h4d: data = 9'b111000;
      8'h4e: data = 9'b111001;
      8'h4f: data = 9'b111010;
      8'h50: data = 9'b111011;
      8'h51: data = 9'b111101;
      8'h52: data = 9'b111110;
      8'h53: data = 9'b111111;
      8'h54: data = 9'b1000001;
      8'h55: data = 9'b1000010;
      8'h56: data = 9'b1000011;
      8'h57: data = 9'b1000101;
      8'h58: data = 9'b1000110;
      8'h59: data = 9'b1000111;
      8'h5a: data = 9'b1001001;
      8'h5b: data = 9'b1001010;
      8'h5c: data = 9'b1001011;
      8'h5d: data = 9'b1001101;
      8'h5e: data = 9'b1001110;
      8'h5f: data = 9'b1010000;
      8'h60: data = 9'b1010001;
      8'h61: data = 9'b1010010;
      8'h62: data = 9'b1010100;
      8'h63: data = 9'b1010101;
      8'h64: data = 9'b1010111;
      8'h65: data = 9'b1011000;
      8'h66: data = 9'b1011010;
      8'h67: data = 9'b1011011;
      8'h68: data = 9'b1011100;
      8'h69: data = 9'b1011110;
      8'h6a: data = 9'b1011111;
      8'h6b: data = 9'b1100001;
      8'h6c: data = 9'b1100010;
      8'h6d: data = 9'b1100100;
      8'h6e: data = 9'b1100101;
      8'h6f: data = 9'b1100111;
      8'h70: data = 9'b1101000;
      8'h71: data = 9'b1101010;
      8'h72: data = 9'b1101011;
      8'h73: data = 9'b1101101;
      8'h74: data = 9'b1101110;
      8'h75: data = 9'b1110000;
      8'h76: data = 9'b1110001;
      8'h77: data = 9'b1110011;
      8'h78: data = 9'b1110100;
      8'h79: data = 9'b1110110;
      8'h7a: data = 9'b1110111;
      8'h7b: data = 9'b1111001;
      8'h7c: data = 9'b1111010;
      8'h7d: data = 9'b1111100;
      8'h7e: data = 9'b1111101;
      8'h7f: data = 9'b1111111;
      8'h80: data = 9'b10000000;
      8'h81: data = 9'b10000001;
      8'h82: data = 9'b10000011;
      8'h83: data = 9'b10000100;
      8'h84: data = 9'b10000110;
      8'h85: data = 9'b10000111;
      8'h86: data = 9'b10001001;
      8'h87: data = 9'b10001010;
      8'h88: data = 9'b10001100;
      8'h89: data = 9'b10001101;
      8'h8a: data = 9'b10001111;
      8'h8b: data = 9'b10010000;
      8'h8c: data = 9'b10010010;
      8'h8d: data = 9'b10010011;
      8'h8e: data = 9'b10010101;
      8'h8f: data = 9'b10010110;
      8'h90: data = 9'b10011000;
      8'h91: data = 9'b10011001;
      8'h92: data = 9'b10011011;
      8'h93: data = 9'b10011100;
      8'h94: data = 9'b10011110;
      8'h95: data = 9'b10011111;
      8'h96: data = 9'b10100001;
      8'h97: data = 9'b10100010;
      8'h98: data = 9'b10100100;
      8'h99: data = 9'b10100101;
      8'h9a: data = 9'b10100110;
      8'h9b: data = 9'b10101000;
      8'h9c: data = 9'b10101001;
      8'h9d: data = 9'b10101011;
      8'h9e: data = 9'b10101100;
      8'h9f: data = 9'b10101110;
      8'ha0: data = 9'b10101111;
      8'ha1: data = 9'b10110000;
      8'ha2: data = 9'b10110010;
      8'ha3: data = 9'b10110011;
      8'ha4: data = 9'b10110101;
      8'ha5: data = 9'b10110110;
      8'ha6: data = 9'b10110111;
      8'ha7: data = 9'b10111001;
      8'ha8: data = 9'b10111010;
      8'ha9: data = 9'b10111011;
      8'haa: data = 9'b10111101;
      8'hab: data = 9'b10111110;
      8'hac: data = 9'b10111111;
      8'had: data = 9'b11000001;
      8'hae: data = 9'b11000010;
      8'haf: data = 9'b11000011;
      8'hb0: data = 9'b11000101;
      8'hb1: data = 9'b11000110;
      8'hb2: data = 9'b11000111;
      8'hb3: data = 9'b11001000;
      8'hb4: data = 9'b11001010;
      8'hb5: data = 9'b11001011;
      8'hb6: data = 9'b11001100;
      8'hb7: data = 9'b11001101;
      8'hb8: data = 9'b11001111;
      8'hb9: data = 9'b11010000;
      8'hba: data = 9'b11010001;
      8'hbb: data = 9'b11010010;
      8'hbc: data = 9'b11010011;
      8'hbd: data = 9'b11010101;
      8'hbe: data = 9'b11010110;
      8'hbf: data = 9'b11010111;
      8'hc0: data = 9'b11011000;
      8'hc1: data = 9'b11011001;
      8'hc2: data = 9'b11011010;
      8'hc3: data = 9'b11011011;
      8'hc4: data = 9'b11011100;
      8'hc5: data = 9'b11011101;
      8'hc6: data = 9'b11011111;
      8'hc7: data = 9'b11100000;
      8'hc8: data = 9'b11100001;
      8'hc9: data = 9'b11100010;
      8'hca: data = 9'b11100011;
      8'hcb: data = 9'b11100100;
      8'hcc: data = 9'b11100101;
      8'hcd: data = 9'b11100110;
      8'hce: data = 9'b11100111;
      8'hcf: data = 9'b11100111;
      8'hd0: data = 9'b11101000;
      8'hd1: data = 9'b11101001;
      8'hd2: data = 9'b11101010;
      8'hd3: data = 9'b11101011;
      8'hd4: data = 9'b11101100;
      8'hd5: data = 9'b11101101;
      8'hd6: data = 9'b11101110;
      8'hd7: data = 9'b11101110;
      8'hd8: data = 9'b11101111;
      8'hd9: data = 9'b11110000;
      8'hda: data = 9'b11110001;
      8'hdb: data = 9'b11110010;
      8'hdc: data = 9'b11110010;
      8'hdd: data = 9'b11110011;
      8'hde: data = 9'b11110100;
      8'hdf: data = 9'b11110100;
      8'he0: data = 9'b11110101;
      8'he1: data = 9'b11110110;
      8'he2: data = 9'b11110110;
      8'he3: data = 9'b11110111;
      8'he4: data = 9'b11110111;
      8'he5: data = 9'b11111000;
      8'he6: data = 9'b11111001;
      8'he7: data = 9'b11111001;
      8'he8: data = 9'b11111010;
      8'he9: data = 9'b11111010;
      8'hea: data = 9'b11111011;
      8'heb: data = 9'b11111011;
      8'hec: data = 9'b11111100;
      8'hed: data = 9'b11111100;
      8'hee: data = 9'b11111100;
      8'hef: data = 9'b11111101;
      8'hf0: data = 9'b11111101;
      8'hf1: data = 9'b11111101;
      8'hf2: data = 9'b11111110;
      8'hf3: data = 9'b11111110;
      8'hf4: data = 9'b11111110;
      8'hf5: data = 9'b11111111;
      8'hf6: data = 9'b11111111;
      8'hf7: data = 9'b11111111;
      8'hf8: data = 9'b11111111;
      8'hf9: data = 9'b11111111;
      8'hfa: data = 9'b100000000;
      8'hfb: data = 9'b100000000;
      8'hfc: data = 9'b100000000;
      8'hfd: data = 9'b100000000;
      8'hfe: data = 9'b100000000;
      8'hff: data = 9'b100000000;
      default: data = 9'b0;
    endcase
            
endmodule // texture_filter$weight$1$rom


module texture_filter$weight$2(alpha,gaussian,w);
    
    // Module arguments
    input wire  [7:0] alpha;
    input wire  gaussian;
    output reg  [8:0] w;
    
    // Constant declarations
    localparam  down = 8'h0;
    localparam  up = 8'h0;
    
    // Stub signals
    reg  [7:0] rom$address;
    wire  [8:0] rom$data;
    
    // Sub module instances
    texture_filter$weight$2$rom rom(
        .address(rom$address),
        .data(rom$data)
    );
    
    // Update code
    always @(*) begin
        rom$address = alpha;
        w = ((alpha >> down) & 9'h1ff) << up;
        if (gaussian) begin
            w = rom$data;
        end
    end
    
endmodule // texture_filter$weight$2


module texture_filter$weight$2$rom(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [8:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 9'b0;
      8'h1: data = 9'b0;
      8'h2: data = 9'b0;
      8'h3: data = 9'b0;
      8'h4: data = 9'b0;
      8'h5: data = 9'b0;
      8'h6: data = 9'b0;
      8'h7: data = 9'b1;
      8'h8: data = 9'b1;
      8'h9: data = 9'b1;
      8'ha: data = 9'b1;
      8'hb: data = 9'b1;
      8'hc: data = 9'b10;
      8'hd: data = 9'b10;
      8'he: data = 9'b10;
      8'hf: data = 9'b11;
      8'h10: data = 9'b11;
      8'h11: data = 9'b11;
      8'h12: data = 9'b100;
      8'h13: data = 9'b100;
      8'h14: data = 9'b100;
      8'h15: data = 9'b101;
      8'h16: data = 9'b101;
      8'h17: data = 9'b110;
      8'h18: data = 9'b110;
      8'h19: data = 9'b111;
      8'h1a: data = 9'b111;
      8'h1b: data = 9'b1000;
      8'h1c: data = 9'b1001;
      8'h1d: data = 9'b1001;
      8'h1e: data = 9'b1010;
      8'h1f: data = 9'b1010;
      8'h20: data = 9'b1011;
      8'h21: data = 9'b1100;
      8'h22: data = 9'b1100;
      8'h23: data = 9'b1101;
      8'h24: data = 9'b1110;
      8'h25: data = 9'b1110;
      8'h26: data = 9'b1111;
      8'h27: data = 9'b10000;
      8'h28: data = 9'b10001;
      8'h29: data = 9'b10010;
      8'h2a: data = 9'b10010;
      8'h2b: data = 9'b10011;
      8'h2c: data = 9'b10100;
      8'h2d: data = 9'b10101;
      8'h2e: data = 9'b10110;
      8'h2f: data = 9'b10111;
      8'h30: data = 9'b11000;
      8'h31: data = 9'b11001;
      8'h32: data = 9'b11001;
      8'h33: data = 9'b11010;
      8'h34: data = 9'b11011;
      8'h35: data = 9'b11100;
      8'h36: data = 9'b11101;
      8'h37: data = 9'b11110;
      8'h38: data = 9'b11111;
      8'h39: data = 9'b100000;
      8'h3a: data = 9'b100001;
      8'h3b: data = 9'b100011;
      8'h3c: data = 9'b100100;
      8'h3d: data = 9'b100101;
      8'h3e: data = 9'b100110;
      8'h3f: data = 9'b100111;
      8'h40: data = 9'b101000;
      8'h41: data = 9'b101001;
      8'h42: data = 9'b101010;
      8'h43: data = 9'b101011;
      8'h44: data = 9'b101101;
      8'h45: data = 9'b101110;
      8'h46: data = 9'b101111;
      8'h47: data = 9'b110000;
      8'h48: data = 9'b110001;
      8'h49: data = 9'b110011;
      8'h4a: data = 9'b110100;
      8'h4b: data = 9'b110101;
      8'h4c: data = 9'b110110;
      8'h4d: data = 9'b111000;
      8'h4e: data = 9'b111001;
      8'h4f: data = 9'b111010;
      8'h50: data = 9'b111011;
      8'h51: data = 9'b111101;
      8'h52: data = 9'b111110;
      8'h53: data = 9'b111111;
      8'h54: data = 9'b1000001;
      8'h55: data = 9'b1000010;
      8'h56: data = 9'b1000011;
      8'h57: data = 9'b1000101;
      8'h58: data = 9'b1000110;
      8'h59: data = 9'b1000111;
      8'h5a: data = 9'b1001001;
      8'h5b: data = 9'b1001010;
      8'h5c: data = 9'b1001011;
      8'h5d: data = 9'b1001101;
      8'h5e: data = 9'b1001110;
      8'h5f: data = 9'b1010000;
      8'h60: data = 9'b1010001;
      8'h61: data = 9'b1010010;
      8'h62: data = 9'b1010100;
      8'h63: data = 9'b1010101;
      8'h64: data = 9'b1010111;
      8'h65: data = 9'b1011000;
      8'h66: data = 9'b1011010;
      8'h67: data = 9'b1011011;
      8'h68: data = 9'b1011100;
      8'h69: data = 9'b1011110;
      8'h6a: data = 9'b1011111;
      8'h6b: data = 9'b1100001;
      8'h6c: data = 9'b1100010;
      8'h6d: data = 9'b1100100;
      8'h6e: data = 9'b1100101;
      8'h6f: data = 9'b1100111;
      8'h70: data = 9'b1101000;
      8'h71: data = 9'b1101010;
      8'h72: data = 9'b1101011;
      8'h73: data = 9'b1101101;
      8'h74: data = 9'b1101110;
      8'h75: data = 9'b1110000;
      8'h76: data = 9'b1110001;
      8'h77: data = 9'b1110011;
      8'h78: data = 9'b1110100;
      8'h79: data = 9'b1110110;
      8'h7a: data = 9'b1110111;
      8'h7b: data = 9'b1111001;
      8'h7c: data = 9'b1111010;
      8'h7d: data = 9'b1111100;
      8'h7e: data = 9'b1111101;
      8'h7f: data = 9'b1111111;
      8'h80: data = 9'b10000000;
      8'h81: data = 9'b10000001;
      8'h82: data = 9'b10000011;
      8'h83: data = 9'b10000100;
      8'h84: data = 9'b10000110;
      8'h85: data = 9'b10000111;
      8'h86: data = 9'b10001001;
      8'h87: data = 9'b10001010;
      8'h88: data = 9'b10001100;
      8'h89: data = 9'b10001101;
      8'h8a: data = 9'b10001111;
      8'h8b: data = 9'b10010000;
      8'h8c: data = 9'b10010010;
      8'h8d: data = 9'b10010011;
      8'h8e: data = 9'b10010101;
      8'h8f: data = 9'b10010110;
      8'h90: data = 9'b10011000;
      8'h91: data = 9'b10011001;
      8'h92: data = 9'b10011011;
      8'h93: data = 9'b10011100;
      8'h94: data = 9'b10011110;
      8'h95: data = 9'b10011111;
      8'h96: data = 9'b10100001;
      8'h97: data = 9'b10100010;
      8'h98: data = 9'b10100100;
      8'h99: data = 9'b10100101;
      8'h9a: data = 9'b10100110;
      8'h9b: data = 9'b10101000;
      8'h9c: data = 9'b10101001;
      8'h9d: data = 9'b10101011;
      8'h9e: data = 9'b10101100;
      8'h9f: data = 9'b10101110;
      8'ha0: data = 9'b10101111;
      8'ha1: data = 9'b10110000;
      8'ha2: data = 9'b10110010;
      8'ha3: data = 9'b10110011;
      8'ha4: data = 9'b10110101;
      8'ha5: data = 9'b10110110;
      8'ha6: data = 9'b10110111;
      8'ha7: data = 9'b10111001;
      8'ha8: data = 9'b10111010;
      8'ha9: data = 9'b10111011;
      8'haa: data = 9'b10111101;
      8'hab: data = 9'b10111110;
      8'hac: data = 9'b10111111;
      8'had: data = 9'b11000001;
      8'hae: data = 9'b11000010;
      8'haf: data = 9'b11000011;
      8'hb0: data = 9'b11000101;
      8'hb1: data = 9'b11000110;
      8'hb2: data = 9'b11000111;
      8'hb3: data = 9'b11001000;
      8'hb4: data = 9'b11001010;
      8'hb5: data = 9'b11001011;
      8'hb6: data = 9'b11001100;
      8'hb7: data = 9'b11001101;
      8'hb8: data = 9'b11001111;
      8'hb9: data = 9'b11010000;
      8'hba: data = 9'b11010001;
      8'hbb: data = 9'b11010010;
      8'hbc: data = 9'b11010011;
      8'hbd: data = 9'b11010101;
      8'hbe: data = 9'b11010110;
      8'hbf: data = 9'b11010111;
      8'hc0: data = 9'b11011000;
      8'hc1: data = 9'b11011001;
      8'hc2: data = 9'b11011010;
      8'hc3: data = 9'b11011011;
      8'hc4: data = 9'b11011100;
      8'hc5: data = 9'b11011101;
      8'hc6: data = 9'b11011111;
      8'hc7: data = 9'b11100000;
      8'hc8: data = 9'b11100001;
      8'hc9: data = 9'b11100010;
      8'hca: data = 9'b11100011;
      8'hcb: data = 9'b11100100;
      8'hcc: data = 9'b11100101;
      8'hcd: data = 9'b11100110;
      8'hce: data = 9'b11100111;
      8'hcf: data = 9'b11100111;
      8'hd0: data = 9'b11101000;
      8'hd1: data = 9'b11101001;
      8'hd2: data = 9'b11101010;
      8'hd3: data = 9'b11101011;
      8'hd4: data = 9'b11101100;
      8'hd5: data = 9'b11101101;
      8'hd6: data = 9'b11101110;
      8'hd7: data = 9'b11101110;
      8'hd8: data = 9'b11101111;
      8'hd9: data = 9'b11110000;
      8'hda: data = 9'b11110001;
      8'hdb: data = 9'b11110010;
      8'hdc: data = 9'b11110010;
      8'hdd: data = 9'b11110011;
      8'hde: data = 9'b11110100;
      8'hdf: data = 9'b11110100;
      8'he0: data = 9'b11110101;
      8'he1: data = 9'b11110110;
      8'he2: data = 9'b11110110;
      8'he3: data = 9'b11110111;
      8'he4: data = 9'b11110111;
      8'he5: data = 9'b11111000;
      8'he6: data = 9'b11111001;
      8'he7: data = 9'b11111001;
      8'he8: data = 9'b11111010;
      8'he9: data = 9'b11111010;
      8'hea: data = 9'b11111011;
      8'heb: data = 9'b11111011;
      8'hec: data = 9'b11111100;
      8'hed: data = 9'b11111100;
      8'hee: data = 9'b11111100;
      8'hef: data = 9'b11111101;
      8'hf0: data = 9'b11111101;
      8'hf1: data = 9'b11111101;
      8'hf2: data = 9'b11111110;
      8'hf3: data = 9'b11111110;
      8'hf4: data = 9'b11111110;
      8'hf5: data = 9'b11111111;
      8'hf6: data = 9'b11111111;
      8'hf7: data = 9'b11111111;
      8'hf8: data = 9'b11111111;
      8'hf9: data = 9'b11111111;
      8'hfa: data = 9'b100000000;
      8'hfb: data = 9'b100000000;
      8'hfc: data = 9'b100000000;
      8'hfd: data = 9'b100000000;
      8'hfe: data = 9'b100000000;
      8'hff: data = 9'b100000000;
      default: data = 9'b0;
    endcase
            
endmodule // texture_filter$weight$2$rom


module texture_filter$weight$3(alpha,gaussian,w);
    
    // Module arguments
    input wire  [7:0] alpha;
    input wire  gaussian;
    output reg  [8:0] w;
    
    // Constant declarations
    localparam  down = 8'h0;
    localparam  up = 8'h0;
    
    // Stub signals
    reg  [7:0] rom$address;
    wire  [8:0] rom$data;
    
    // Sub module instances
    texture_filter$weight$3$rom rom(
        .address(rom$address),
        .data(rom$data)
    );
    
    // Update code
    always @(*) begin
        rom$address = alpha;
        w = ((alpha >> down) & 9'h1ff) << up;
        if (gaussian) begin
            w = rom$data;
        end
    end
    
endmodule // texture_filter$weight$3


module texture_filter$weight$3$rom(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [8:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 9'b0;
      8'h1: data = 9'b0;
      8'h2: data = 9'b0;
      8'h3: data = 9'b0;
      8'h4: data = 9'b0;
      8'h5: data = 9'b0;
      8'h6: data = 9'b0;
      8'h7: data = 9'b1;
      8'h8: data = 9'b1;
      8'h9: data = 9'b1;
      8'ha: data = 9'b1;
      8'hb: data = 9'b1;
      8'hc: data = 9'b10;
      8'hd: data = 9'b10;
      8'he: data = 9'b10;
      8'hf: data = 9'b11;
      8'h10: data = 9'b11;
      8'h11: data = 9'b11;
      8'h12: data = 9'b100;
      8'h13: data = 9'b100;
      8'h14: data = 9'b100;
      8'h15: data = 9'b101;
      8'h16: data = 9'b101;
      8'h17: data = 9'b110;
      8'h18: data = 9'b110;
      8'h19: data = 9'b111;
      8'h1a: data = 9'b111;
      8'h1b: data = 9'b1000;
      8'h1c: data = 9'b1001;
      8'h1d: data = 9'b1001;
      8'h1e: data = 9'b1010;
      8'h1f: data = 9'b1010;
      8'h20: data = 9'b1011;
      8'h21: data = 9'b1100;
      8'h22: data = 9'b1100;
      8'h23: data = 9'b1101;
      8'h24: data = 9'b1110;
      8'h25: data = 9'b1110;
      8'h26: data = 9'b1111;
      8'h27: data = 9'b10000;
      8'h28: data = 9'b10001;
      8'h29: data = 9'b10010;
      8'h2a: data = 9'b10010;
      8'h2b: data = 9'b10011;
      8'h2c: data = 9'b10100;
      8'h2d: data = 9'b10101;
      8'h2e: data = 9'b10110;
      8'h2f: data = 9'b10111;
      8'h30: data = 9'b11000;
      8'h31: data = 9'b11001;
      8'h32: data = 9'b11001;
      8'h33: data = 9'b11010;
      8'h34: data = 9'b11011;
      8'h35: data = 9'b11100;
      8'h36: data = 9'b11101;
      8'h37: data = 9'b11110;
      8'h38: data = 9'b11111;
      8'h39: data = 9'b100000;
      8'h3a: data = 9'b100001;
      8'h3b: data = 9'b100011;
      8'h3c: data = 9'b100100;
      8'h3d: data = 9'b100101;
      8'h3e: data = 9'b100110;
      8'h3f: data = 9'b100111;
      8'h40: data = 9'b101000;
      8'h41: data = 9'b101001;
      8'h42: data = 9'b101010;
      8'h43: data = 9'b101011;
      8'h44: data = 9'b101101;
      8'h45: data = 9'b101110;
      8'h46: data = 9'b101111;
      8'h47: data = 9'b110000;
      8'h48: data = 9'b110001;
      8'h49: data = 9'b110011;
      8'h4a: data = 9'b110100;
      8'h4b: data = 9'b110101;
      8'h4c: data = 9'b110110;
      8'h4d: data = 9'b111000;
      8'h4e: data = 9'b111001;
      8'h4f: data = 9'b111010;
      8'h50: data = 9'b111011;
      8'h51: data = 9'b111101;
      8'h52: data = 9'b111110;
      8'h53: data = 9'b111111;
      8'h54: data = 9'b1000001;
      8'h55: data = 9'b1000010;
      8'h56: data = 9'b1000011;
      8'h57: data = 9'b1000101;
      8'h58: data = 9'b1000110;
      8'h59: data = 9'b1000111;
      8'h5a: data = 9'b1001001;
      8'h5b: data = 9'b1001010;
      8'h5c: data = 9'b1001011;
      8'h5d: data = 9'b1001101;
      8'h5e: data = 9'b1001110;
      8'h5f: data = 9'b1010000;
      8'h60: data = 9'b1010001;
      8'h61: data = 9'b1010010;
      8'h62: data = 9'b1010100;
      8'h63: data = 9'b1010101;
      8'h64: data = 9'b1010111;
      8'h65: data = 9'b1011000;
      8'h66: data = 9'b1011010;
      8'h67: data = 9'b1011011;
      8'h68: data = 9'b1011100;
      8'h69: data = 9'b1011110;
      8'h6a: data = 9'b1011111;
      8'h6b: data = 9'b1100001;
      8'h6c: data = 9'b1100010;
      8'h6d: data = 9'b1100100;
      8'h6e: data = 9'b1100101;
      8'h6f: data = 9'b1100111;
      8'h70: data = 9'b1101000;
      8'h71: data = 9'b1101010;
      8'h72: data = 9'b1101011;
      8'h73: data = 9'b1101101;
      8'h74: data = 9'b1101110;
      8'h75: data = 9'b1110000;
      8'h76: data = 9'b1110001;
      8'h77: data = 9'b1110011;
      8'h78: data = 9'b1110100;
      8'h79: data = 9'b1110110;
      8'h7a: data = 9'b1110111;
      8'h7b: data = 9'b1111001;
      8'h7c: data = 9'b1111010;
      8'h7d: data = 9'b1111100;
      8'h7e: data = 9'b1111101;
      8'h7f: data = 9'b1111111;
      8'h80: data = 9'b10000000;
      8'h81: data = 9'b10000001;
      8'h82: data = 9'b10000011;
      8'h83: data = 9'b10000100;
      8'h84: data = 9'b10000110;
      8'h85: data = 9'b10000111;
      8'h86: data = 9'b10001001;
      8'h87: data = 9'b10001010;
      8'h88: data = 9'b10001100;
      8'h89: data = 9'b10001101;
      8'h8a: data = 9'b10001111;
      8'h8b: data = 9'b10010000;
      8'h8c: data = 9'b10010010;
      8'h8d: data = 9'b10010011;
      8'h8e: data = 9'b10010101;
      8'h8f: data = 9'b10010110;
      8'h90: data = 9'b10011000;
      8'h91: data = 9'b10011001;
      8'h92: data = 9'b10011011;
      8'h93: data = 9'b10011100;
      8'h94: data = 9'b10011110;
      8'h95: data = 9'b10011111;
      8'h96: data = 9'b10100001;
      8'h97: data = 9'b10100010;
      8'h98: data = 9'b10100100;
      8'h99: data = 9'b10100101;
      8'h9a: data = 9'b10100110;
      8'h9b: data = 9'b10101000;
      8'h9c: data = 9'b10101001;
      8'h9d: data = 9'b10101011;
      8'h9e: data = 9'b10101100;
      8'h9f: data = 9'b10101110;
      8'ha0: data = 9'b10101111;
      8'ha1: data = 9'b10110000;
      8'ha2: data = 9'b10110010;
      8'ha3: data = 9'b10110011;
      8'ha4: data = 9'b10110101;
      8'ha5: data = 9'b10110110;
      8'ha6: data = 9'b10110111;
      8'ha7: data = 9'b10111001;
      8'ha8: data = 9'b10111010;
      8'ha9: data = 9'b10111011;
      8'haa: data = 9'b10111101;
      8'hab: data = 9'b10111110;
      8'hac: data = 9'b10111111;
      8'had: data = 9'b11000001;
      8'hae: data = 9'b11000010;
      8'haf: data = 9'b11000011;
      8'hb0: data = 9'b11000101;
      8'hb1: data = 9'b11000110;
      8'hb2: data = 9'b11000111;
      8'hb3: data = 9'b11001000;
      8'hb4: data = 9'b11001010;
      8'hb5: data = 9'b11001011;
      8'hb6: data = 9'b11001100;
      8'hb7: data = 9'b11001101;
      8'hb8: data = 9'b11001111;
      8'hb9: data = 9'b11010000;
      8'hba: data = 9'b11010001;
      8'hbb: data = 9'b11010010;
      8'hbc: data = 9'b11010011;
      8'hbd: data = 9'b11010101;
      8'hbe: data = 9'b11010110;
      8'hbf: data = 9'b11010111;
      8'hc0: data = 9'b11011000;
      8'hc1: data = 9'b11011001;
      8'hc2: data = 9'b11011010;
      8'hc3: data = 9'b11011011;
      8'hc4: data = 9'b11011100;
      8'hc5: data = 9'b11011101;
      8'hc6: data = 9'b11011111;
      8'hc7: data = 9'b11100000;
      8'hc8: data = 9'b11100001;
      8'hc9: data = 9'b11100010;
      8'hca: data = 9'b11100011;
      8'hcb: data = 9'b11100100;
      8'hcc: data = 9'b11100101;
      8'hcd: data = 9'b11100110;
      8'hce: data = 9'b11100111;
      8'hcf: data = 9'b11100111;
      8'hd0: data = 9'b11101000;
      8'hd1: data = 9'b11101001;
      8'hd2: data = 9'b11101010;
      8'hd3: data = 9'b11101011;
      8'hd4: data = 9'b11101100;
      8'hd5: data = 9'b11101101;
      8'hd6: data = 9'b11101110;
      8'hd7: data = 9'b11101110;
      8'hd8: data = 9'b11101111;
      8'hd9: data = 9'b11110000;
      8'hda: data = 9'b11110001;
      8'hdb: data = 9'b11110010;
      8'hdc: data = 9'b11110010;
      8'hdd: data = 9'b11110011;
      8'hde: data = 9'b11110100;
      8'hdf: data = 9'b11110100;
      8'he0: data = 9'b11110101;
      8'he1: data = 9'b11110110;
      8'he2: data = 9'b11110110;
      8'he3: data = 9'b11110111;
      8'he4: data = 9'b11110111;
      8'he5: data = 9'b11111000;
      8'he6: data = 9'b11111001;
      8'he7: data = 9'b11111001;
      8'he8: data = 9'b11111010;
      8'he9: data = 9'b11111010;
      8'hea: data = 9'b11111011;
      8'heb: data = 9'b11111011;
      8'hec: data = 9'b11111100;
      8'hed: data = 9'b11111100;
      8'hee: data = 9'b11111100;
      8'hef: data = 9'b11111101;
      8'hf0: data = 9'b11111101;
      8'hf1: data = 9'b11111101;
      8'hf2: data = 9'b11111110;
      8'hf3: data = 9'b11111110;
      8'hf4: data = 9'b11111110;
      8'hf5: data = 9'b11111111;
      8'hf6: data = 9'b11111111;
      8'hf7: data = 9'b11111111;
      8'hf8: data = 9'b11111111;
      8'hf9: data = 9'b11111111;
      8'hfa: data = 9'b100000000;
      8'hfb: data = 9'b100000000;
      8'hfc: data = 9'b100000000;
      8'hfd: data = 9'b100000000;
      8'hfe: data = 9'b100000000;
      8'hff: data = 9'b100000000;
      default: data = 9'b0;
    endcase
            
endmodule // texture_filter$weight$3$rom
